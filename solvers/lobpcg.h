// LOBPCG (Knyazev 2001): the smallest eigenpairs of a graph Laplacian on the
// complement of the constant vector, preconditioned by an AMG V-cycle. It
// gives lambda_2 in near-linear time where shift-invert Lanczos needs a sparse
// factorization (docs/method.md).
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "solvers/block_kernels.h"
#include "solvers/smoothed_aggregation.h"

namespace unfold {

struct LobpcgOptions {
  /// stop when |M x_0 - lambda_0 B x_0| <= tolerance lambda_0 |B x_0|. The Rayleigh
  /// quotient's error is of the order of the residual squared: 1e-4 gives lambda_2 to
  /// 1e-11 relative on the shared meshes, in 12 iterations where 1e-7 took 17.
  double tolerance = 1e-4;
  int max_iterations = 1000;
  uint64_t seed = 1;  ///< start block (fixed: reproducible)
};

struct LobpcgResult {
  Eigen::Vector3d values;   ///< the three smallest eigenvalues off the constant vector, ascending
  Eigen::MatrixXd vectors;  ///< n x 3, B-orthonormal, B-orthogonal to 1
  int iterations = 0;
  double relative_residual = 0;  ///< of the smallest pair
  bool converged = false;
};

/// The three smallest eigenpairs of M x = lambda B x (B = diag(b); b empty: B =
/// I) restricted to vectors B-orthogonal to 1 (zero-mean for B = I); the
/// smallest is converged to `tolerance`, the other two help it along.
/// @param M symmetric positive semi-definite, M 1 = 0, at least 12 rows
/// @param preconditioner AMG hierarchy of M (or of a matrix spectrally close to it)
/// @param b B's diagonal: empty, or n positive entries
/// @throws UsageError if M has fewer than 12 rows or b is not as above
LobpcgResult lobpcg_smallest(const CsrView& M, const AmgData& preconditioner,
                             const LobpcgOptions& options = {},
                             const Eigen::VectorXd& b = Eigen::VectorXd());

}  // namespace unfold
