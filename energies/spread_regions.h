// Soft geodesic regions for the local spread (stretch.local, docs/method.md,
// local spread): the stretch term's spread taken within overlapping regions of
// the rest shape instead of about its one centroid.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// A partition of unity over `count` regions: weights (vertex i, region k,
/// w_ik), w_ik > 0, sum_k w_ik = 1 for every vertex; and the share `local` in
/// [0, 1) of the spread taken within the regions (the rest about the centroid).
struct SpreadRegions {
  int count = 0;
  double local = 0;
  std::vector<Eigen::Triplet<double>> weights;
};

struct SpreadRegionsOptions {
  double local = 0;     ///< share of the spread within the regions, in [0, 1)
  double radius = 0.3;  ///< the regions' Gaussian width, times the geodesic diameter
  int count = 32;       ///< regions: farthest-point landmarks along the edges
};

/// Regions around `count` landmarks picked by farthest-point sampling of the
/// graph geodesics of the rest shape V (the first the vertex farthest from
/// vertex 0): w_ik proportional to exp(-g_ik^2 / (2 s^2)), g_ik the geodesic
/// distance from landmark k, s = radius times the largest geodesic distance
/// met (about the diameter). Weights below 1e-4 of a vertex's largest are left
/// out. Geodesics make the regions follow the shape, not its pose: a hand's
/// region does not take in the hip it touches.
/// @param V     rest positions (n x 3) of the graph's vertices
/// @param graph edge graph (connected, or at least `count` landmarks reach every part)
/// @throws UsageError if V and graph disagree, count < 1, radius <= 0, local
///         outside [0, 1), or a vertex is reached by no landmark
SpreadRegions spread_regions(const Eigen::MatrixX3d& V, const EdgeGraph& graph,
                             const SpreadRegionsOptions& options);

}  // namespace unfold
