// model/elements.cpp: the finite elements' forces, Jacobian and energy (elements.h).

#include "model/elements.h"

#include <algorithm>
#include <cmath>

#include "core/assert.h"

namespace jello {

double meanElementMass(const Body& body, const Material& material) {
  return material.density * restVolume(body) / body.count();
}

namespace {

Block3 toBlock(const Mat3x3& m) {
  Block3 b;
  for (int e = 0; e < 9; ++e) b.m[e] = m.m[e];
  return b;
}

// The outer product a b^T.
Mat3x3 outer(Vec3 a, Vec3 b) { return fromColumns(b.x * a, b.y * a, b.z * a); }

}  // namespace

ElementTerm::ElementTerm(const Body& body, std::vector<Material> byPart,
                         const std::vector<double>& pointMass)
    : ForceTerm(body.count()), material_(std::move(byPart)) {
  const int n = body.count();
  const std::size_t parts = body.joined() ? body.parts.size() : 1;
  JELLO_ASSERT(material_.size() == parts);
  JELLO_ASSERT(pointMass.size() == std::size_t(n));
  damping_.assign(n, 0.0);
  for (std::size_t part = 0; part < parts; ++part) {
    const Material& m = material_[part];
    lame_.push_back(lameOf(m));
    if (!m.elements()) continue;
    const Body& own = body.joined() ? *body.parts[part] : body;
    const int first = body.joined() ? body.partFirst[part] : 0;
    for (const Tet& local : tetrahedraOf(own)) {
      Element el;
      const Vec3 x0 = own.restPosition(local[0]);
      const Mat3x3 dm =
          fromColumns(own.restPosition(local[1]) - x0, own.restPosition(local[2]) - x0,
                      own.restPosition(local[3]) - x0);
      el.volume = determinant(dm) / 6;
      JELLO_ASSERT(el.volume > 0);
      const Mat3x3 g = inverse(dm);
      el.b[1] = g.row(0), el.b[2] = g.row(1), el.b[3] = g.row(2);
      el.b[0] = -1.0 * (el.b[1] + el.b[2] + el.b[3]);
      for (int a = 0; a < 4; ++a) el.t[a] = local[a] + first;
      el.part = static_cast<int>(part);
      elements_.push_back(el);
    }
    if (m.massDamping != 0) {
      massDamping_ = true;
      for (int q = first; q < first + own.count(); ++q) damping_[q] = m.massDamping * pointMass[q];
    }
  }
  indexElements(n);
}

void ElementTerm::indexElements(int n) {
  firstElement_.assign(n, -1);
  lastElement_.assign(n, -1);
  // Each point's elements (CSR), then its row of the Jacobian: the points its elements join it
  // to, sorted; the rows one after another are the couplings, (row, column) ascending.
  std::vector<int> start(n + 1, 0);
  for (int e = 0; e < elementCount(); ++e)
    for (int q : elements_[e].t) {
      if (firstElement_[q] < 0) firstElement_[q] = e;
      lastElement_[q] = e;
      ++start[q + 1];
    }
  for (int q = 0; q < n; ++q) start[q + 1] += start[q];
  std::vector<int> of(start[n]), at(start.begin(), start.end() - 1);
  for (int e = 0; e < elementCount(); ++e)
    for (int q : elements_[e].t) of[at[q]++] = e;
  std::vector<int> rowStart(n + 1, 0), row;
  couplings_.clear();
  for (int q = 0; q < n; ++q) {
    row.clear();
    for (int k = start[q]; k < start[q + 1]; ++k)
      for (int c : elements_[of[k]].t) row.push_back(c);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    rowStart[q] = static_cast<int>(couplings_.size());
    for (int c : row) couplings_.push_back({q, c});
  }
  rowStart[n] = static_cast<int>(couplings_.size());
  slots_.resize(elements_.size());
  for (int e = 0; e < elementCount(); ++e)
    for (int a = 0; a < 4; ++a) {
      const int q = elements_[e].t[a];
      const auto first = couplings_.begin() + rowStart[q],
                 last = couplings_.begin() + rowStart[q + 1];
      for (int c = 0; c < 4; ++c)
        slots_[e][4 * a + c] = static_cast<int>(
            std::lower_bound(first, last, std::pair{q, elements_[e].t[c]}) - couplings_.begin());
    }
}

Mat3x3 ElementTerm::gradientOf(const Element& el, const double* a) const {
  const int n = pointCount();
  Mat3x3 f;
  for (int k = 0; k < 4; ++k) {
    const Vec3 b = el.b[k];
    for (int i = 0; i < 3; ++i) {
      const double x = a[coordIndex(el.t[k], i, n)];
      f.m[3 * i] += x * b.x;
      f.m[3 * i + 1] += x * b.y;
      f.m[3 * i + 2] += x * b.z;
    }
  }
  return f;
}

Mat3x3 ElementTerm::deformation(int e, const double* p) const {
  return gradientOf(elements_[e], p);
}

Mat3x3 ElementTerm::stress(const Element& el, const double* p, const double* v) const {
  const Material& m = material_[el.part];
  const Mat3x3 f = gradientOf(el, p);
  Mat3x3 stress = firstPiola(m.kind, lame_[el.part], f);
  if (m.stiffnessDamping != 0)
    stress = stress + viscousStress(lame_[el.part], m.stiffnessDamping, f, gradientOf(el, v));
  return stress;
}

double ElementTerm::vonMises(int e, const double* p) const {
  const Element& el = elements_[e];
  const Mat3x3 f = gradientOf(el, p);
  const double j = determinant(f);
  if (std::fabs(j) < 1e-12) return 0;
  const Mat3x3 sigma =
      (1 / j) * firstPiola(material_[el.part].kind, lame_[el.part], f) * transpose(f);
  const Mat3x3 s = symmetric(sigma);
  const double mean = trace(s) / 3;
  const Mat3x3 dev = s - mean * identity3();
  return std::sqrt(1.5 * contract(dev, dev));
}

void ElementTerm::addForcesOn(PointRange points, const double* p, const double* v, const Bounds*,
                              double* force) const {
  if (points.begin >= points.end) return;
  // The elements with a point in the range: all of them for the whole body, else those between
  // its points' first and last.
  const bool whole = points.begin == 0 && points.end == pointCount();
  int lo = whole ? 0 : elementCount(), hi = whole ? elementCount() - 1 : -1;
  if (!whole)
    for (int q = points.begin; q < points.end; ++q)
      if (firstElement_[q] >= 0)
        lo = std::min(lo, firstElement_[q]), hi = std::max(hi, lastElement_[q]);
  auto inRange = [&](int q) { return q >= points.begin && q < points.end; };
  for (int e = lo; e <= hi; ++e) {
    const Element& el = elements_[e];
    if (!inRange(el.t[0]) && !inRange(el.t[1]) && !inRange(el.t[2]) && !inRange(el.t[3])) continue;
    const Mat3x3 s = stress(el, p, v);
    for (int a = 0; a < 4; ++a)
      if (inRange(el.t[a])) addAt(force, el.t[a], -el.volume * (s * el.b[a]));
  }
  if (massDamping_)
    for (int q = points.begin; q < points.end; ++q)
      if (damping_[q] != 0) addAt(force, q, -damping_[q] * at(v, q));
}

void ElementTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  for (int e = 0; e < elementCount(); ++e) {
    const Element& el = elements_[e];
    const Material& m = material_[el.part];
    const Lame lame = lame_[el.part];
    const Mat3x3 f = gradientOf(el, p);
    const Mat3x3 fdot = gradientOf(el, v);
    const StressDerivative derivative(m.kind, lame, f);
    const bool viscous = m.stiffnessDamping != 0;
    // Column j of block (a, c) is -V dP b_a for dF = e_j b_c^T (point c moved along axis j).
    Mat3x3 byP[4][4], byV[4][4];
    for (int c = 0; c < 4; ++c)
      for (int j = 0; j < 3; ++j) {
        const Vec3 axis{double(j == 0), double(j == 1), double(j == 2)};
        const Mat3x3 df = outer(axis, el.b[c]);
        Mat3x3 dp = derivative.apply(df);
        Mat3x3 dv;
        if (viscous) {
          dp = dp + viscousStressByF(lame, m.stiffnessDamping, f, fdot, df);
          dv = viscousStressByRate(lame, m.stiffnessDamping, f, df);
        }
        for (int a = 0; a < 4; ++a) {
          byP[a][c].setColumn(j, -el.volume * (dp * el.b[a]));
          byV[a][c].setColumn(j, -el.volume * (dv * el.b[a]));
        }
      }
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c)
        sink->addCoupling(slots_[e][4 * a + c], toBlock(byP[a][c]), toBlock(byV[a][c]));
  }
  if (massDamping_)
    for (int q = 0; q < pointCount(); ++q)
      if (damping_[q] != 0) {
        Block3 dv;
        for (int axis = 0; axis < 3; ++axis) dv.m[4 * axis] = -damping_[q];
        sink->addPoint(q, Block3{}, dv);
      }
}

void ElementTerm::addEnergy(const double* p, double* energy) const {
  for (const Element& el : elements_)
    *energy +=
        el.volume * energyDensity(material_[el.part].kind, lame_[el.part], gradientOf(el, p));
}

void ElementTerm::summarise(std::vector<std::string>* kept,
                            std::vector<std::string>* leftOut) const {
  bool viscous = false;
  for (const Material& m : material_)
    viscous = viscous || m.stiffnessDamping != 0 || m.massDamping != 0;
  kept->push_back("finite elements");
  if (viscous)
    kept->push_back("Rayleigh damping");
  else
    leftOut->push_back("Rayleigh damping (zero damping)");
}

std::vector<TermLine> ElementTerm::describe(const double*) const {
  std::vector<int> count(material_.size(), 0);
  for (const Element& el : elements_) ++count[el.part];
  std::vector<TermLine> lines;
  for (std::size_t part = 0; part < material_.size(); ++part) {
    const Material& m = material_[part];
    if (!m.elements()) continue;
    const std::string who = material_.size() > 1 ? textf("jelly %zu: ", part + 1) : std::string();
    lines.push_back(
        {"elements", who + textf("%d tetrahedra of %s, E = %g Pa, nu = %g, density %g kg/m^3; "
                                 "Rayleigh damping alpha = %g 1/s, beta = %g s",
                                 count[part], materialInfo(m.kind).what, m.youngsModulus,
                                 m.poissonRatio, m.density, m.massDamping, m.stiffnessDamping)});
  }
  return lines;
}

}  // namespace jello
