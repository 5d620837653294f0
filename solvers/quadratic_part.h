// The quadratic part of the energy, assembled once per mesh from the terms'
// capability interfaces: what the local-global solver's global step solves
// with, and what decides whether the energy is bounded at a beta.
//
// With the rotations fixed, every quadratic term t contributes
// w_t(beta) (tr(Q^T H_t Q) - 2 tr(Q^T B_t(R)) + c_t(R)); the global step solves
//   A(beta) Q = sum_t w_t(beta) B_t(R),   A(beta) = sum_t w_t(beta) H_t,
// on zero-mean Q. A is split by whether a term scales with beta, so that a new
// beta only refills values: A = A_fixed + beta A_beta. B_t and c_t of the terms
// that do not depend on R (no RotationTerm) are summed here once as well.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/unfold_problem.h"

namespace unfold {

struct QuadraticPart {
  /// sum of w_t H_t over terms not scaled by beta: their growth Hessians
  /// (EnergyTerm::add_growth_hessian), H for quadratic terms
  Eigen::SparseMatrix<double> A_fixed;
  Eigen::SparseMatrix<double> A_beta;  ///< the same at beta = 1 over the terms scaled by beta
  /// sum of w_t B_t over the quadratic terms free of R, not scaled / scaled (at beta = 1)
  Eigen::MatrixX3d B_fixed, B_beta;
  double c_fixed = 0, c_beta = 0;  ///< the same for c_t
  /// columns sqrt(w_t) u_t of the terms' rank_one_hessian(): the true A_fixed is
  /// A_fixed + U U^T (n x 0 when no term has one)
  Eigen::MatrixXd U_fixed;
  /// columns sqrt(w_t) of the terms' region_hessian(), also in U_fixed: the
  /// direct global step adds them by Woodbury's identity (the rank-one parts it
  /// needs not add)
  Eigen::MatrixXd U_regions;
};

/// A_fixed and A_beta on one pattern (the union of all terms', explicit zeros
/// kept, so that A_fixed + beta A_beta keeps it), U_fixed, and the constant B and c parts.
/// @throws UsageError if a term scaled by beta has a rank-one Hessian part (none does)
QuadraticPart assemble_quadratic_part(const UnfoldProblem& problem);

/// Whether the quadratic part at beta is bounded below off the constant vector:
/// A(beta) has one negative pivot at most (the stretch term's 1 direction), by
/// one LDL^T factorization. Non-quadratic terms count by their growth Hessians.
/// @throws NumericalError if the factorization breaks down
bool quadratic_part_bounded(const UnfoldProblem& problem, double beta);

}  // namespace unfold
