// The paper's stopping ratio delta (Algorithm 1): mean relative edge length.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

/// delta = (1/m) sum_e |q_i - q_j| / |p_i - p_j| over the m edges (i, j) of the graph.
/// @param P rest positions (n x 3), n = graph.num_vertices
/// @param Q deformed positions (n x 3)
/// @throws UsageError if the sizes disagree
/// @throws InputError if the graph has no edges or an edge has zero rest length
double edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q);

/// The rest length |p_i - p_j| of every graph edge, in graph.edges order: for
/// solvers that evaluate delta every iteration (the overload below).
/// @throws UsageError if the sizes disagree
/// @throws InputError if an edge has zero rest length
Eigen::VectorXd edge_lengths(const EdgeGraph& graph, const Eigen::MatrixX3d& P);

/// delta with the rest lengths precomputed (edge_lengths(graph, P)).
/// @throws UsageError if the sizes disagree
/// @throws InputError if the graph has no edges
double edge_ratio(const EdgeGraph& graph, const Eigen::VectorXd& rest_lengths,
                  const Eigen::MatrixX3d& Q);

/// Per vertex i: the mean of |q_i - q_j| / |p_i - p_j| over its neighbours j (its
/// local stretch; 1 for an isolated vertex).
/// @throws UsageError if the sizes disagree
/// @throws InputError if an edge has zero rest length
Eigen::VectorXd vertex_edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                  const Eigen::MatrixX3d& Q);

}  // namespace unfold
