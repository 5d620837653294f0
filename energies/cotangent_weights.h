// Cotangent weights of a tet mesh's edges (the linear-FEM Laplacian), an
// alternative to the paper's uniform ARAP weights.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// w_ij = (1/6) sum over tets containing edge ij of l_kl cot(theta_kl), with kl
/// the opposite edge and theta_kl the dihedral angle at kl. Such weights can
/// be negative on badly shaped tets; negative and tiny ones are clamped to
/// 1e-3 times the mean weight so every cell keeps a positive-definite fit.
/// @param V vertex positions, T tetrahedra, graph = build_edge_graph(V.rows(), T)
/// @returns one weight per graph edge
std::vector<double> cotangent_weights(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T,
                                      const EdgeGraph& graph);

}  // namespace unfold
