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
  double smoothing_ratio =
      30;  ///< the smoother damps eigenvalues of D^-1 A above lambda_max / ratio
};

struct AmgLevel {
  RowSparse A;                       ///< this level's matrix
  Eigen::VectorXd inverse_diagonal;  ///< D^-1
  double lambda_max = 0;             ///< estimate of the largest eigenvalue of D^-1 A
  RowSparse P;                       ///< prolongation from the next coarser level
  RowSparse R;                       ///< restriction, P^T
  mutable RowMatrixX3d x, b, r, d;   ///< V-cycle work blocks
};

struct AmgData {
  std::vector<AmgLevel> levels;    ///< finest first
  Eigen::MatrixXd coarse_inverse;  ///< pseudo-inverse of the coarsest matrix
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

/// Galerkin coarse operators of two matrices on a hierarchy's levels, for the
/// pencil F + beta B: the unfolding's global matrix is one, and an AMG of
/// the pencil itself (not of the Laplacian alone) also corrects the
/// stretch term's shift on the coarse levels, where it matters most.
struct AmgPencil {
  std::vector<RowSparse> F, B;      ///< per level, one pattern per level
  Eigen::VectorXd coarse_constant;  ///< the constant vector restricted to the coarsest level
};

/// @param data a hierarchy from amg_precomputation (its transfer operators are used)
/// @param F, B symmetric, the size of data's finest level
void amg_pencil_precomputation(const AmgData& data, const Eigen::SparseMatrix<double>& F,
                               const Eigen::SparseMatrix<double>& B, AmgPencil* pencil);

/// Makes every level's operator F_l + beta B_l (smoother data and coarse
/// solve included). When the constant vector is a negative direction of the
/// fine operator (the stretch term's -n I), the coarsest solve adds the
/// rank-one term that flips it, so the cycle stays positive definite on
/// zero-mean vectors.
/// @pre F + beta B has a positive diagonal on every level
void amg_set_pencil(const AmgPencil& pencil, double beta, AmgData* data);

/// One V-cycle for M x = b from x = 0: an approximation of M^+ b, symmetric
/// positive definite in b on the complement of the constant vector.
/// Uses data's work blocks: one `data` must not serve two calls at a time.
/// @param b n x 3; x is resized to n x 3 (may not alias b)
void amg_vcycle(const AmgData& data, const RowMatrixX3d& b, RowMatrixX3d* x);

}  // namespace unfold
