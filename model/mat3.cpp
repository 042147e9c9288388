// model/mat3.cpp: the polar decomposition (mat3.h).

#include "model/mat3.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace jello {

namespace {

// The eigenvalues of the symmetric a (into d) and its eigenvectors (the columns of v, a rotation),
// by cyclic Jacobi rotations until the off-diagonal part is below 1e-15 of the matrix (at most 20
// sweeps; 3x3 matrices take 3 to 5).
void symmetricEigen(Mat3x3 a, Vec3* d, Mat3x3* v) {
  *v = identity3();
  const double scale = contract(a, a);
  for (int sweep = 0; sweep < 20; ++sweep) {
    const double off = a(0, 1) * a(0, 1) + a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2);
    if (!(off > 1e-30 * scale)) break;
    for (auto [p, q] : {std::pair{0, 1}, {0, 2}, {1, 2}}) {
      const double apq = a(p, q);
      if (apq == 0) continue;
      // The rotation in the (p, q) plane that zeroes a(p, q), applied to rows and columns p, q.
      const double theta = (a(q, q) - a(p, p)) / (2 * apq);
      const double t =
          (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
      const double c = 1 / std::sqrt(t * t + 1), s = t * c;
      const int r = 3 - p - q;  // the third index
      const double arp = a(r, p), arq = a(r, q);
      a(p, p) -= t * apq;
      a(q, q) += t * apq;
      a(p, q) = a(q, p) = 0;
      a(r, p) = a(p, r) = c * arp - s * arq;
      a(r, q) = a(q, r) = s * arp + c * arq;
      for (int k = 0; k < 3; ++k) {
        const double vkp = (*v)(k, p), vkq = (*v)(k, q);
        (*v)(k, p) = c * vkp - s * vkq;
        (*v)(k, q) = s * vkp + c * vkq;
      }
    }
  }
  *d = {a(0, 0), a(1, 1), a(2, 2)};
}

}  // namespace

PolarDecomposition polarDecomposition(const Mat3x3& f) {
  Vec3 eigen;
  Mat3x3 v;
  symmetricEigen(transpose(f) * f, &eigen, &v);
  // Largest first.
  double values[3] = {eigen.x, eigen.y, eigen.z};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return values[a] > values[b]; });
  Mat3x3 sorted = fromColumns(v.column(order[0]), v.column(order[1]), v.column(order[2]));
  if (determinant(sorted) < 0) sorted.setColumn(2, -1.0 * sorted.column(2));
  double sigma[3];
  for (int i = 0; i < 3; ++i) sigma[i] = std::sqrt(std::max(values[order[i]], 0.0));
  // U's first two columns from F v_i / sigma_i (the largest stretches, the best defined), the third
  // their cross product so that det U = +1; sigma_3 then takes F's orientation's sign.
  Vec3 u[3];
  const Vec3 fallback[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 2; ++i) {
    const Vec3 w = f * sorted.column(i);
    double len;
    u[i] = direction(w, &len);
    if (len <= 1e-12 * (sigma[0] + 1e-300)) {
      // A collapsed direction: any unit vector orthogonal to the ones before.
      Vec3 pick = fallback[0];
      for (const Vec3& candidate : fallback)
        if (i == 0 || std::fabs(dot(candidate, u[0])) < 0.9) {
          pick = candidate;
          break;
        }
      if (i == 1) pick = pick - dot(pick, u[0]) * u[0];
      u[i] = direction(pick, &len);
    } else if (i == 1) {
      const Vec3 w1 = u[1] - dot(u[1], u[0]) * u[0];
      u[1] = direction(w1, &len);
    }
  }
  u[2] = cross(u[0], u[1]);
  if (determinant(f) < 0) sigma[2] = -sigma[2];
  const Mat3x3 uu = fromColumns(u[0], u[1], u[2]);
  PolarDecomposition out;
  out.rotation = uu * transpose(sorted);
  Mat3x3 diagonal;
  diagonal.m[0] = sigma[0], diagonal.m[4] = sigma[1], diagonal.m[8] = sigma[2];
  out.stretch = sorted * diagonal * transpose(sorted);
  out.singular = {sigma[0], sigma[1], sigma[2]};
  out.axes = sorted;
  return out;
}

Mat3x3 rotationOf(const Mat3x3& f) {
  Mat3x3 cof = cofactor(f);
  double det = dot(f.column(0), cof.column(0));
  const double size = contract(f, f);
  if (!(det > 1e-6 * size * std::sqrt(size))) return polarDecomposition(f).rotation;
  Mat3x3 r = f;
  for (int iteration = 0; iteration < 30; ++iteration) {
    // Scaled while det R is far from 1 (where it speeds the first steps); near it, plain.
    const double g = std::fabs(det - 1) < 0.1 ? 1.0 : std::cbrt(1 / det);
    // R^-T = cof(R) / det R.
    const double a = 0.5 * g, b = 0.5 / (g * det);
    double change = 0;
    for (int e = 0; e < 9; ++e) {
      const double next = a * r.m[e] + b * cof.m[e];
      change += (next - r.m[e]) * (next - r.m[e]);
      r.m[e] = next;
    }
    // Quadratic convergence: after a change below 1e-8 the iterate is exact to rounding.
    if (change < 1e-16) break;
    cof = cofactor(r);
    det = dot(r.column(0), cof.column(0));
  }
  return r;
}

}  // namespace jello
