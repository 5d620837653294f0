// A coarse graph of a surface, for solving the surface stages on fewer
// vertices (simplify.surface_solve_hops, docs/performance.md): the surface's
// vertices grouped into connected clusters, one coarse vertex per cluster at
// its centroid, clusters joined where a surface edge joins them. Unlike a
// decimation it takes linear time, and the clusters depend on the
// connectivity alone: every pose of one mesh gets the same coarse graph, so
// the surface solve's pose invariance is not lost to where clusters fall.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"
#include "mesh/surface_mesh.h"

namespace unfold {

struct SurfaceCoarsening {
  std::vector<int> cluster_of;  ///< each surface vertex's cluster (coarse vertex)
  Eigen::MatrixX3d V;           ///< the clusters' area-weighted centroids
  Eigen::VectorXd masses;       ///< the clusters' areas (sums of lumped vertex areas)
  EdgeGraph graph;              ///< clusters joined by some surface edge
};

/// Groups the vertices of `surface` into clusters: in vertex order, each
/// vertex no cluster holds starts one, which claims the unclaimed vertices
/// within `hops` surface edges of it (reached through its own vertices, so
/// every cluster is connected). On a regular triangle mesh one hop leaves
/// about a quarter of the vertices, two about a tenth.
/// @param surface  a triangle (or polygon) surface, every vertex in a face
/// @param hops     the clusters' radius in edges, >= 1
/// @throws UsageError if hops < 1; InputError if a vertex has no area (lumped_masses)
SurfaceCoarsening coarsen_surface(const SurfaceMesh& surface, int hops);

}  // namespace unfold
