// Preconditioned conjugate gradients for the global step on the complement of
// the constant vector, where its matrix is positive definite when the energy
// is bounded: the iterative alternative to the sparse LDL^T for large meshes.
// The three coordinate columns are solved side by side (one CG per column,
// shared matrix and preconditioner passes).
#pragma once

#include <Eigen/Core>

#include "solvers/block_kernels.h"
#include "solvers/smoothed_aggregation.h"

namespace unfold {

struct CgOptions {
  /// Column k stops when |r_k| <= max(tolerance |b_k|, forcing |r0_k|), r0 the
  /// warm start's residual: an absolute floor, and a relative reduction that
  /// keeps early outer iterations (big steps) from being over-solved.
  double tolerance = 1e-8;
  double forcing = 0;
  int max_iterations = 500;
  /// true: A is singular on the constant vector and x, r and the directions are
  /// kept zero-mean; false: A is positive definite and no mean is removed
  bool zero_mean = true;
};

struct CgResult {
  int iterations = 0;
  double relative_residual = 0;  ///< max over columns of |r_k| / |b_k|
  bool converged = false;
  bool negative_curvature = false;  ///< p^T A p <= 0 met: A is not definite off 1
};

/// CG's work vectors, kept between solves so that they allocate nothing.
struct CgWorkspace {
  RowMatrixX3d r, z, p, q;
};

/// Solves (A + U U^T) x = b for zero-mean x, from the zero-mean part of *x (warm
/// start), preconditioned by one V-cycle of `preconditioner` (an AMG hierarchy
/// of a Laplacian spectrally close to A up to scale). A column meeting negative
/// curvature stops moving and the result says so. With options.zero_mean false,
/// A x = b for a positive definite A (a Laplacian plus a positive diagonal), from *x.
/// @param U optional low-rank part (n x k; null or k = 0: none)
/// @pre A + U U^T symmetric, maps zero-mean blocks to zero-mean blocks; b zero-mean; *x has
///      A.rows rows (zero_mean false: A symmetric positive definite, any b)
CgResult projected_cg(const CsrView& A, const AmgData& preconditioner, const RowMatrixX3d& b,
                      RowMatrixX3d* x, const CgOptions& options, CgWorkspace* workspace = nullptr,
                      const Eigen::MatrixXd* U = nullptr);

}  // namespace unfold
