// The paper's delta (Algorithm 1): the mean over edges of deformed / rest length.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

/// (1/m) sum_e |q_i - q_j| / |p_i - p_j| over the graph's edges.
/// @pre no edge of zero rest length
double edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q);

}  // namespace unfold
