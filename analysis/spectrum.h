// spectrum.h: a few eigenpairs of the sparse, symmetric kNumCoords x kNumCoords matrices of the
// stability analysis (stability.h), without a dense eigensolver on all of them (seconds each):
// Lanczos iterations (Spectra) for the largest eigenvalues and for those nearest a shift, and
// the rest lattice's mirror symmetries for all of its eigenvalues.
//
// Every function takes a symmetric matrix (only its lower triangle is read where said) and
// returns eigenvalues in the matrix's units, eigenvectors as unit columns. Nothing is kept
// between calls.
#pragma once

#include <optional>

#include "solver/jacobian.h"  // Eigen, and the SparseMatrix of the Jacobians

namespace jello {

struct Eigenpairs {
  Eigen::VectorXd values;   // descending
  Eigen::MatrixXd vectors;  // kNumCoords rows, one unit column per value
};

// The `count` algebraically largest eigenvalues of `matrix` and their eigenvectors (implicitly
// restarted Lanczos, from Spectra's fixed starting vector: the same answer every run). Nothing
// when the iteration does not converge.
std::optional<Eigenpairs> largestEigenpairs(const SparseMatrix& matrix, int count);

struct AboveShift {
  Eigenpairs pairs;
  // How many eigenvalues of `matrix` lie below the shift: the negative pivots of the LDL^T
  // factorisation of matrix - shift I (Sylvester's law of inertia), so all of them, not only
  // those near it.
  int below = 0;
};
// The `count` smallest eigenvalues of `matrix` above `shift` and their eigenvectors (Lanczos on
// (matrix - shift I)^-1, factorised once, for its largest eigenvalues: those above the shift and
// nearest it). Nothing when the factorisation breaks down (the shift is an eigenvalue) or the
// iteration does not converge.
std::optional<AboveShift> eigenpairsAbove(const SparseMatrix& matrix, double shift, int count);

// The `count` eigenvalues of `matrix` nearest `shift`, above or below it, and their eigenvectors
// (Lanczos on (matrix - shift I)^-1, factorised once). Nothing when the factorisation breaks down
// or the iteration does not converge.
std::optional<Eigenpairs> eigenpairsNear(const SparseMatrix& matrix, double shift, int count);

// The Ritz pairs of `matrix` on the Krylov space of `start` of dimension `steps` (Lanczos,
// reorthogonalised in full, no restart): `steps` values (fewer when the space is invariant, or
// has fewer dimensions than `steps`) and
// unit vectors, and the residual |matrix y - value y| of each (matrix's units). Those at the ends
// of the spectrum converge first; a Ritz vector inside it is a mixture of the eigenvectors near
// its value, weighted as `start` weights them.
struct RitzPairs {
  Eigenpairs pairs;
  Eigen::VectorXd residuals;
};
RitzPairs ritzPairs(const SparseMatrix& matrix, const Eigen::VectorXd& start, int steps);

// All kNumCoords eigenvalues, ascending, of a matrix on the lattice's coordinates that commutes
// with the three mirror reflections of the lattice through its centre (i -> 7 - i with x -> -x,
// and the same for j, y and k, z): the rest lattice's stiffness. In the basis of displacements
// even or odd under each reflection the matrix falls apart into 8 blocks of kNumCoords / 8, each
// solved densely: about 60 times less work than the whole matrix.
Eigen::VectorXd mirrorSymmetricEigenvalues(const SparseMatrix& matrix);
// Every eigenvalue of `matrix` and, along each eigenvector phi, the Rayleigh quotient
// phi^T other phi of a second matrix (units of each), in no order, when both commute with the
// three mirrors: from the 8 blocks of each, their eigenvectors never leaving the blocks. Nothing
// when either does not (a deformed cube, a contact on one side).
struct Eigenquotients {
  Eigen::VectorXd values, quotients;  // kNumCoords each, paired by index
};
std::optional<Eigenquotients> mirrorSymmetricQuotients(const SparseMatrix& matrix,
                                                       const SparseMatrix& other);

}  // namespace jello
