// The best rotation of every cell of an edge graph from rest to current
// positions (paper Eq. 2 with uniform weights): what the rigidity metrics
// measure against and what places interior vertices. The solver's local step
// is fit_rotations (solvers/unfold_problem.h), over the energy's rotation terms.
#pragma once

#include <Eigen/Core>

#include "geometry/rotations.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// For every vertex i: R_i = argmin_R sum_{j in N_i} |(q_i - q_j) - R (p_i - p_j)|^2,
/// in parallel over vertices. Isolated vertices get the identity.
/// @param rest    rest positions p (n x 3)
/// @param current current positions q (n x 3)
/// @param R       output, resized to n
void best_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                    const Eigen::MatrixX3d& current, Rotations* R);

}  // namespace unfold
