// Shortest-path (graph geodesic) distances along mesh edges.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// Single-source Dijkstra in the graph with Euclidean edge lengths |p_i - p_j|.
/// @param P      positions (n x 3), n = graph.num_vertices
/// @param source vertex in [0, n)
/// @return distance to every vertex; +infinity where unreachable
/// @throws UsageError if P has the wrong size or source is out of range
std::vector<double> graph_geodesics(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int source);

}  // namespace unfold
