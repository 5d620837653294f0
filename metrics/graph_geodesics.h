// Shortest-path (graph geodesic) distances along mesh edges.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// One CSR neighbour entry with its Euclidean length |p_i - p_j|. Packed to 12
/// bytes: a Dijkstra run reads a vertex's entries in one stream, and that read
/// is most of its time (docs/history/performance.md, issue 15's "Fourth pass").
#pragma pack(push, 4)
struct NeighborArc {
  int neighbor;
  double length;
};
#pragma pack(pop)

/// Every CSR neighbour entry of a graph with its length (in graph.neighbors
/// order): computed once, shared by many Dijkstra runs.
struct NeighborLengths {
  std::vector<NeighborArc> arcs;
  double shortest = 0;  ///< over all entries (0 for a graph without edges)
  double longest = 0;
};

/// @throws UsageError if P has the wrong size
NeighborLengths neighbor_lengths(const EdgeGraph& graph, const Eigen::MatrixX3d& P);

/// Single-source shortest paths with the given lengths: a bucket queue (Dial)
/// whose buckets are max(shortest, longest / 32) wide, a vertex relaxed again
/// whenever a vertex of its own bucket improves it, so the result is exact (the
/// shortest path's length, summed along the path); a binary heap when the
/// lengths are too uneven for buckets.
/// @param lengths  neighbor_lengths(graph, P)
/// @param source   vertex in [0, n)
/// @param distance resized to n: the distance to every vertex, +infinity where unreachable
/// @throws UsageError if lengths has the wrong size or source is out of range
void graph_geodesics(const EdgeGraph& graph, const NeighborLengths& lengths, int source,
                     std::vector<double>* distance);

/// The same with Euclidean edge lengths |p_i - p_j| from positions P (n x 3).
std::vector<double> graph_geodesics(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int source);

}  // namespace unfold
