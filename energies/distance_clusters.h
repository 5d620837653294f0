// Clusters of a graph's vertices for the spread by distances
// (energies/distance_spread_energy.h): the graph-Voronoi cells of seeds placed
// by farthest-point sampling along the edges of the rest shape. Lengths along
// the edges, not through space, so a cell follows the shape: a hand's cell
// does not take in the hip it touches.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// Each vertex's cell in [0, cells): the first seed is vertex 0, each next one
/// the vertex farthest (along the edges, lengths |v_i - v_j|) from the seeds so
/// far, and every vertex belongs to its nearest seed. A part of the graph that
/// no seed reaches is seeded next, so every part has a cell while seeds remain.
/// @param V     rest positions (n x 3) of the graph's vertices
/// @param count seeds wanted; at most n are placed
/// @param cells set to the number of cells made
/// @throws UsageError if V and graph disagree or count < 1, InputError if the
///         graph has more connected parts than `count`
std::vector<int> distance_clusters(const Eigen::MatrixX3d& V, const EdgeGraph& graph, int count,
                                   int* cells);

/// distance_clusters' result: each vertex's cell, and how many cells.
struct DistanceClusters {
  std::vector<int> cell_of;
  int count = 0;
};

/// The same as a DistanceClusters.
DistanceClusters make_distance_clusters(const Eigen::MatrixX3d& V, const EdgeGraph& graph,
                                        int count);

}  // namespace unfold
