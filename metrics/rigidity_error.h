// E_rig (paper Eq. 8): how far each cell's deformation is from a rotation.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

struct RigidityError {
  double mean = 0;             ///< E_rig = (1/n) sum_i per_vertex(i)
  Eigen::VectorXd per_vertex;  ///< sum_{j in N_i} |q_i - q_j - R_i(p_i - p_j)| / |p_i - p_j|
};

/// E_rig = (1/n) sum_i sum_{j in N_i} |q_i - q_j - R_i (p_i - p_j)| / |p_i - p_j|,
/// with R_i the best rotation of cell i (best_rotations(), Eq. 2) from P to Q.
/// Zero for any rigid motion. Parallel over vertices, deterministic.
/// @param graph cells N_i; num_vertices = n > 0
/// @param P     rest positions (n x 3)
/// @param Q     deformed positions (n x 3)
/// @throws UsageError if the sizes disagree or n == 0
/// @throws InputError if an edge has zero rest length
RigidityError rigidity_error(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q);

}  // namespace unfold
