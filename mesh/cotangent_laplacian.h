// The cotangent Laplacian of a triangle mesh (linear finite elements): the
// stiffness matrix of the Laplace-Beltrami operator, for its eigenbasis.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace unfold {

/// W with W_ij = -(cot alpha_ij + cot beta_ij) / 2 for each edge ij (alpha, beta the
/// angles opposite it), W_ii = -sum_j W_ij: symmetric, positive semi-definite
/// on a mesh without obtuse-angle pathologies, constants in its kernel.
/// Together with lumped_masses(V, F), W x = lambda M x is the Laplace-Beltrami
/// eigenproblem. A degenerate triangle (zero area) contributes nothing.
/// @param V vertex positions (n x 3)
/// @param F triangles, ids in [0, n)
/// @throws UsageError if F names a vertex outside V
Eigen::SparseMatrix<double> cotangent_laplacian(const Eigen::MatrixX3d& V,
                                                const Eigen::MatrixX3i& F);

}  // namespace unfold
