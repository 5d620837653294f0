// The first eigenfunctions of a surface's Laplace-Beltrami operator: the
// basis of functional maps (ZoomOut) between shapes.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// Eigenpairs W phi = lambda M phi of the cotangent Laplacian W and the lumped
/// mass matrix M (the smallest `count` eigenvalues), phi M-orthonormal.
struct LaplaceBeltramiBasis {
  Eigen::VectorXd values;  ///< count eigenvalues, ascending (the first is ~0)
  Eigen::MatrixXd phi;     ///< n x count, column k the k-th eigenfunction, phi^T M phi = I
  Eigen::VectorXd masses;  ///< the lumped masses M (n)
};

/// The `count` lowest eigenpairs of the cotangent Laplace-Beltrami operator
/// (mesh/cotangent_laplacian.h, mesh/lumped_masses.h) by shift-invert Lanczos
/// (Spectra) with a sparse LDL^T of W - sigma M, sigma slightly below 0.
/// @param V vertex positions (n x 3), F triangles
/// @param count number of eigenpairs, 1 <= count < n
/// @throws UsageError for count out of range; InputError if a vertex has no
///         area; NumericalError if the factorization or the eigensolver fails
LaplaceBeltramiBasis laplace_beltrami_basis(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                                            int count);

}  // namespace unfold
