// solver/statics.cpp: Newton's method for a body at rest (statics.h).

#include "solver/statics.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/jacobian.h"
#include "solver/physics.h"

namespace jello {

namespace {

// The largest force on a free point at positions p (velocities zero), and the forces.
double largestFreeForce(const Model& model, const std::vector<double>& p,
                        const std::vector<char>& pinned, std::vector<double>* force) {
  const std::vector<double> v(p.size(), 0.0);
  force->assign(p.size(), 0.0);
  computeForces(model, p.data(), v.data(), force->data());
  double largest = 0;
  for (std::size_t c = 0; c < p.size(); ++c)
    if (!pinned[c]) largest = std::max(largest, std::fabs((*force)[c]));
  return largest;
}

// Solves K dx = rhs: by LDL^T where K is symmetric (elastic forces, springs, pins), by LU where it
// is not (friction, dampers at a contact) or LDL^T fails. False when K is singular.
bool solveStiffness(const SparseMatrix& k, const Eigen::VectorXd& rhs, Eigen::VectorXd* dx) {
  const SparseMatrix asymmetry = k - SparseMatrix(k.transpose());
  const bool symmetric = asymmetry.norm() <= 1e-12 * k.norm();
  if (symmetric) {
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(k);
    if (ldlt.info() == Eigen::Success) {
      *dx = ldlt.solve(rhs);
      if (ldlt.info() == Eigen::Success && dx->allFinite()) return true;
    }
  }
  Eigen::SparseLU<SparseMatrix> lu(k);
  if (lu.info() != Eigen::Success) return false;
  *dx = lu.solve(rhs);
  return lu.info() == Eigen::Success && dx->allFinite();
}

}  // namespace

StaticSolution solveStatic(const Model& model, const State& start, int maxSteps) {
  const int n = model.points();
  const std::vector<char> pinned = pinnedCoordinates(model.pinned, n);
  std::vector<double> p(start.p(), start.p() + 3 * n), force, trial(3 * n);
  const std::vector<double> zero(3 * n, 0.0);
  StaticSolution out;
  double largest = largestFreeForce(model, p, pinned, &force);
  AccelerationJacobian jacobian;
  for (int step = 0; step < maxSteps; ++step) {
    accelerationJacobian(model, p.data(), zero.data(), nullptr, &jacobian);
    // K = -dF/dp = -M dA/dp, the pinned rows and columns the identity's.
    SparseMatrix k = -jacobian.dAdp;
    for (int column = 0; column < k.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(k, column); it; ++it) {
        const int row = static_cast<int>(it.row());
        const int q = row % n;  // the row's point: coordIndex(q, axis, n) = axis * n + q
        if (pinned[row] || pinned[column])
          it.valueRef() = row == column ? 1.0 : 0.0;
        else
          it.valueRef() *= model.pointMass[q];
      }
    Eigen::VectorXd rhs(3 * n);
    for (int c = 0; c < 3 * n; ++c) rhs[c] = pinned[c] ? 0.0 : force[c];
    Eigen::VectorXd dx;
    if (!solveStiffness(k, rhs, &dx)) break;  // singular: nothing holds the body
    double scale = 1, moved = 0;
    std::vector<double> trialForce;
    for (int halving = 0; halving <= 20; ++halving, scale *= 0.5) {
      for (int c = 0; c < 3 * n; ++c) trial[c] = p[c] + scale * dx[c];
      const double now = largestFreeForce(model, trial, pinned, &trialForce);
      if (std::isfinite(now) && (now <= largest || halving == 20)) {
        largest = now;
        break;
      }
    }
    for (int c = 0; c < 3 * n; ++c) moved = std::max(moved, std::fabs(trial[c] - p[c]));
    p.swap(trial);
    force.swap(trialForce);
    out.steps = step + 1;
    if (moved <= 1e-9 * model.body().spacing) {
      out.converged = true;
      break;
    }
  }
  out.state = State(n);
  std::copy(p.begin(), p.end(), out.state.p());
  out.largestForce = largest;
  return out;
}

}  // namespace jello
