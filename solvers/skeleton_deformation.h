// SCF's third step: the mesh carried along by its skeleton, whose nodes moved
// (straightened by unbend_skeleton): blended rigid motions of the nodes
// (linear blend skinning by the skeleton-vertex correspondence), then ARAP
// anchored to the skinned positions, our substitute for Yan et al.'s simplex
// transformations (docs/baselines.md).
#pragma once

#include <Eigen/Core>

#include "mesh/curve_skeleton.h"
#include "mesh/edge_graph.h"
#include "solvers/unbend_skeleton.h"

namespace unfold {

struct SkeletonDeformationOptions {
  double blend_radius = 0;   ///< skinning weights reach 0 at this distance along the skeleton (> 0)
  double arap_anchor = 0.1;  ///< the refinement's pull to the skinned positions (> 0)
  int arap_iterations = 100;  ///< refinement steps at most (0: skinning alone)
};

struct SkeletonDeformation {
  Eigen::MatrixX3d positions;        ///< every graph vertex, zero mean
  Eigen::MatrixX3d skinned;          ///< the same before the refinement, zero mean
  Eigen::MatrixX3d canonical_nodes;  ///< the moved skeleton nodes where `positions` has them
};

/// Every node gets a rigid motion: the root's rotation best fits the whole
/// rest skeleton onto the moved one, every other node's is its parent's then
/// the least rotation turning its bone into the new direction (a skeleton
/// cannot tell a twist about a bone, so none is added). A vertex (the surface's
/// by skeleton.node_of_vertex, an interior one by its nearest node) follows the
/// motions of the nodes within blend_radius of its own along the skeleton,
/// weighted (1 - (d/r)^2)^2; then arap_solve on the graph (vertex 0 held, the
/// others pulled to their skinned positions). Equivariant under rigid motions.
/// @param graph    edge graph of P (the tet mesh, or the surface)
/// @param P        rest positions; the first skeleton.node_of_vertex.size() rows are the surface's
/// @param skeleton the rest skeleton of P's surface
/// @param unbent   unbend_skeleton of it (its moved nodes, tree and distances)
/// @throws UsageError for bad sizes or options, NumericalError if the result is not finite
SkeletonDeformation deform_by_skeleton(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const CurveSkeleton& skeleton, const UnbentSkeleton& unbent,
                                       const SkeletonDeformationOptions& options);

}  // namespace unfold
