// jacobian.h: the analytic Jacobians of the forces (physics.h) with respect to the positions
// and the velocities, for the implicit integrator and for the stability analysis.
//
// Units: dF/dp in N/m, dF/dv in N s/m; the acceleration Jacobians divide by the mass. Signs
// follow physics.h: each block is the derivative of the force ON a point.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "physics.h"

namespace jello {

using Mat3 = Eigen::Matrix3d;
using SparseMatrix = Eigen::SparseMatrix<double>;
using BlockSlots = std::array<int, 9>;

// Derivatives of springForce(L, relVel, k, d, rest) with respect to L and to relVel. With the
// geometric term: dF/dL = -k [u u^T + (1 - rest/|L|) P] - (d/|L|) [u (P w)^T + (w.u) P], where
// P = I - u u^T and w = relVel; dF/dw = -d u u^T. Zero at |L| = 0, where the force is zero.
void springJacobian(Vec3 L, Vec3 relVel, double k, double d, double rest, Mat3* dFdL, Mat3* dFdw);
// Derivatives of wallForce: -k e e^T and -d e e^T for each wall the point is beyond.
void wallJacobian(Vec3 p, double k, double d, Mat3* dFdp, Mat3* dFdv);
// Derivatives of planeForce: -k n n^T / |n|^2 and -d n n^T / |n|^2 when the point is across.
// `plane` as planeForce takes it (Model::plane, normalised).
void planeJacobian(const Plane& plane, double side, Vec3 p, double k, double d, Mat3* dFdp, Mat3* dFdv);
// Derivative of fieldForce with respect to p: the gradient of the trilinear interpolation
// inside the point's cell; zero outside the box and for R < 2.
Mat3 fieldJacobian(const ForceField& field, Vec3 p);

// Jacobians (kNumCoords x kNumCoords) of the accelerations F/mass of all points with respect
// to all positions and all velocities. Their sparsity pattern is the same for every state and
// for both: a 3x3 block for every point (the diagonal) and for every pair of points a spring
// joins, zeros kept. It is built on the first assembly; later ones only write values.
struct AccelerationJacobian {
  SparseMatrix dAdp, dAdv;
  // Where each block's entries (row-major) are in the value arrays: the 4 blocks (aa, ab, ba,
  // bb) of every spring in order, then the diagonal block of every point. A block's rows are
  // not adjacent in the per-point layout (see coordIndex), so each entry has its own slot.
  std::vector<BlockSlots> blockSlots;
  std::vector<int> diagonal;  // value index of each diagonal entry
};
void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out);

}  // namespace jello
