// Algebraic multigrid by smoothed aggregation (Vanek, Mandel & Brezina 1996)
// for graph Laplacians: the preconditioner that makes the global step and
// lambda_2 near-linear in n where a sparse factorization of a 3D mesh is not
// (fill ~ n^1.4, flops ~ n^2; docs/performance.md). libigl style: the
// hierarchy is built once per mesh (amg_precomputation) and one V-cycle is
// applied per preconditioner call (amg_vcycle).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "solvers/block_kernels.h"

namespace unfold {

struct AmgOptions {
  int coarse_size = 400;     ///< stop coarsening at this many unknowns (dense solve there)
  int max_levels = 20;       ///< levels at most
  double strength = 0.0;     ///< strong connection: |a_ij| > strength sqrt(a_ii a_jj)
  int smoothing_degree = 2;  ///< Chebyshev polynomial degree, pre and post
  /// the smoother damps the eigenvalues of D^-1 A in [lambda_max / ratio, lambda_max]
  double smoothing_ratio = 10;
  /// true: the smoother's lambda_max is Gershgorin's bound, never below the true
  /// one, so the V-cycle stays positive definite (the power steps' estimate can
  /// fall below it on a large mesh, and the smoother then amplifies the modes
  /// above it); false: the power steps' estimate, raised by 10 %, a faster smoother
  bool gershgorin_lambda_max = false;
  /// V-cycle in float (the hierarchy is built in double): its sparse products
  /// move half the bytes, 10-15 % off the global step at 75k vertices
  /// (docs/history/performance.md). A preconditioner need only be close to M^+; the
  /// solvers' own products and residuals stay in double.
  bool single_precision = true;
};

template <typename Scalar>
struct AmgLevelOf {
  using Sparse = Eigen::SparseMatrix<Scalar, Eigen::RowMajor>;
  Sparse A;                                                   ///< this level's matrix
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> inverse_diagonal;  ///< D^-1
  double lambda_max = 0;                   ///< estimate of the largest eigenvalue of D^-1 A
  Sparse P;                                ///< prolongation from the next coarser level
  Sparse R;                                ///< restriction, P^T
  mutable RowMatrixX3<Scalar> x, b, r, d;  ///< V-cycle work blocks
};
using AmgLevel = AmgLevelOf<double>;

struct AmgData {
  std::vector<AmgLevel> levels;    ///< finest first
  Eigen::MatrixXd coarse_inverse;  ///< pseudo-inverse of the coarsest matrix
  /// With options.single_precision: the levels and coarse inverse in float, for the V-cycle.
  std::vector<AmgLevelOf<float>> single_levels;
  Eigen::MatrixXf single_coarse_inverse;
  AmgOptions options;
  double operator_complexity = 0;  ///< nonzeros of all levels / nonzeros of the finest
};

/// Builds the hierarchy for M.
/// @param M symmetric positive semi-definite with non-positive off-diagonal
///          entries and rows summing to zero (a weighted graph Laplacian of a
///          connected graph); explicit zeros in the pattern are allowed
/// @throws UsageError if M is not square or has a non-positive diagonal entry
void amg_precomputation(const Eigen::SparseMatrix<double>& M, const AmgOptions& options,
                        AmgData* data);

/// One V-cycle for M x = b from x = 0: an approximation of M^+ b, symmetric
/// positive definite in b on the complement of the constant vector (to float
/// rounding with options.single_precision).
/// Uses data's work blocks: one `data` must not serve two calls at a time.
/// @param b n x 3; x is resized to n x 3 (may not alias b)
void amg_vcycle(const AmgData& data, const RowMatrixX3d& b, RowMatrixX3d* x);

}  // namespace unfold
