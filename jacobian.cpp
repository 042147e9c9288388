// jacobian.cpp: analytic derivatives of the force terms, assembled as sparse matrices.

#include "jacobian.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jello {

namespace {

Eigen::Vector3d col(Vec3 a) { return {a.x, a.y, a.z}; }

// The shared pattern and the index of every block in it.
void buildPattern(const Model& model, AccelerationJacobian* out) {
  std::vector<Eigen::Triplet<double>> entries;
  auto block = [&](int row, int column) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) entries.emplace_back(coordIndex(row, i), coordIndex(column, j), 0.0);
  };
  std::vector<std::pair<int, int>> blocks;
  for (const Spring& s : model.springs)
    for (auto [row, column] : {std::pair{s.a, s.a}, {s.a, s.b}, {s.b, s.a}, {s.b, s.b}}) blocks.push_back({row, column});
  for (int q = 0; q < kNumPoints; ++q) blocks.push_back({q, q});
  for (auto [row, column] : blocks) block(row, column);
  SparseMatrix pattern(kNumCoords, kNumCoords);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  out->dAdp = pattern;
  out->dAdv = pattern;
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  auto find = [&](int row, int column) {
    const int* at = std::lower_bound(inner + outer[column], inner + outer[column + 1], row);
    return static_cast<int>(at - inner);
  };
  out->blockSlots.clear();
  for (auto [row, column] : blocks) {
    BlockSlots slots;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) slots[3 * i + j] = find(coordIndex(row, i), coordIndex(column, j));
    out->blockSlots.push_back(slots);
  }
  out->diagonal.resize(kNumCoords);
  for (int i = 0; i < kNumCoords; ++i) out->diagonal[i] = find(i, i);
}

void addBlock(double* values, const BlockSlots& slots, const Mat3& block, double scale) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) values[slots[3 * i + j]] += scale * block(i, j);
}

}  // namespace

void springJacobian(Vec3 L, Vec3 relVel, double k, double d, double rest, Mat3* dFdL, Mat3* dFdw) {
  double len;
  Eigen::Vector3d u = col(direction(L, &len));
  if (len == 0) {
    dFdL->setZero();
    dFdw->setZero();
    return;
  }
  Eigen::Vector3d w = col(relVel);
  Mat3 uu = u * u.transpose();
  Mat3 P = Mat3::Identity() - uu;
  *dFdL = -k * (uu + (1 - rest / len) * P) - (d / len) * (u * (P * w).transpose() + u.dot(w) * P);
  *dFdw = -d * uu;
}

void wallJacobian(Vec3 p, double k, double d, Mat3* dFdp, Mat3* dFdv) {
  dFdp->setZero();
  dFdv->setZero();
  const double coord[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; ++axis) {
    if (std::fabs(coord[axis]) <= kBoxHalfSize) continue;
    (*dFdp)(axis, axis) -= k;
    (*dFdv)(axis, axis) -= d;
  }
}

void planeJacobian(const Plane& plane, double side, Vec3 p, double k, double d, Mat3* dFdp, Mat3* dFdv) {
  if (!(planeValue(plane, p) * side < 0)) {
    dFdp->setZero();
    dFdv->setZero();
    return;
  }
  Eigen::Vector3d n(plane.a, plane.b, plane.c);
  Mat3 nn = n * n.transpose() / n.squaredNorm();
  *dFdp = -k * nn;
  *dFdv = -d * nn;
}

Mat3 fieldJacobian(const ForceField& field, Vec3 p) {
  Mat3 J = Mat3::Zero();
  const int r = field.resolution;
  // Outside the box, or not a number (which fails every comparison): no field, no gradient.
  if (r < 2 || !(std::fabs(p.x) <= kBoxHalfSize && std::fabs(p.y) <= kBoxHalfSize &&
                 std::fabs(p.z) <= kBoxHalfSize))
    return J;
  const double coord[3] = {p.x, p.y, p.z};
  const double perMetre = (r - 1) / (2 * kBoxHalfSize);  // dt/dx of the cell coordinate
  int cell[3];
  double t[3];
  for (int axis = 0; axis < 3; ++axis) {
    double g = (coord[axis] + kBoxHalfSize) * (r - 1) / (2 * kBoxHalfSize);
    // g is in [0, r - 1] inside the box; clamped before the conversion all the same.
    cell[axis] = static_cast<int>(std::floor(std::clamp(g, 0.0, r - 2.0)));
    t[axis] = g - cell[axis];
  }
  for (int corner = 0; corner < 8; ++corner) {
    const int bit[3] = {(corner >> 2) & 1, (corner >> 1) & 1, corner & 1};
    double factor[3], slope[3];
    for (int a = 0; a < 3; ++a) {
      factor[a] = bit[a] ? t[a] : 1 - t[a];
      slope[a] = bit[a] ? perMetre : -perMetre;
    }
    std::size_t node = (static_cast<std::size_t>(cell[0] + bit[0]) * r + (cell[1] + bit[1])) * r + (cell[2] + bit[2]);
    Eigen::Vector3d f = col(field.node(node));
    Eigen::Vector3d dw(slope[0] * factor[1] * factor[2], factor[0] * slope[1] * factor[2],
                       factor[0] * factor[1] * slope[2]);
    J += f * dw.transpose();
  }
  return J;
}

void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out) {
  if (out->blockSlots.size() != 4 * model.springs.size() + kNumPoints) buildPattern(model, out);
  const World& w = model.world;
  const double perMass = 1.0 / w.mass;
  double* dp = out->dAdp.valuePtr();
  double* dv = out->dAdv.valuePtr();
  std::fill(dp, dp + out->dAdp.nonZeros(), 0.0);
  std::fill(dv, dv + out->dAdv.nonZeros(), 0.0);
  std::size_t slot = 0;
  Mat3 dFdL, dFdw;
  for (const Spring& s : model.springs) {
    springJacobian(load(p, s.a) - load(p, s.b), load(v, s.a) - load(v, s.b), w.kElastic, w.dElastic, s.rest, &dFdL,
                   &dFdw);
    for (double sign : {1.0, -1.0, -1.0, 1.0}) {  // aa, ab, ba, bb
      addBlock(dp, out->blockSlots[slot], dFdL, sign * perMass);
      addBlock(dv, out->blockSlots[slot], dFdw, sign * perMass);
      ++slot;
    }
  }
  Mat3 wallP, wallV, planeP, planeV;
  for (int q = 0; q < kNumPoints; ++q, ++slot) {
    Vec3 pq = load(p, q);
    wallJacobian(pq, w.kCollision, w.dCollision, &wallP, &wallV);
    Mat3 blockP = wallP + fieldJacobian(w.field, pq), blockV = wallV;
    if (w.hasPlane) {
      planeJacobian(model.plane, model.planeSide, pq, w.kCollision, w.dCollision, &planeP, &planeV);
      blockP += planeP;
      blockV += planeV;
    }
    if (pull && pull->point == q) blockP -= pull->stiffness * Mat3::Identity();
    addBlock(dp, out->blockSlots[slot], blockP, perMass);
    addBlock(dv, out->blockSlots[slot], blockV, perMass);
  }
}

}  // namespace jello
