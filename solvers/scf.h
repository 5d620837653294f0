// The SCF baseline (Pickup, Sun, Rosin, Martin, "Skeleton-based canonical forms
// for non-rigid 3D shape retrieval", 2016; the paper's comparison): extract the
// curve skeleton with its vertex correspondence (mesh/curve_skeleton.h),
// straighten it by MDS keeping the bone lengths (solvers/unbend_skeleton.h),
// then carry the mesh along: each vertex follows the rigid motions of the
// skeleton nodes near its own (linear blend skinning), and an ARAP solve on
// the whole edge graph anchored to the skinned positions smooths the joints.
// The ARAP refinement stands in for Yan et al.'s simplex transformations
// (docs/baselines.md).
#pragma once

#include <Eigen/Core>

#include "mesh/curve_skeleton.h"
#include "mesh/edge_graph.h"
#include "solvers/unbend_skeleton.h"

namespace unfold {

struct ScfOptions {
  CurveSkeletonOptions skeleton;
  int mds_iterations = 300;  ///< Guttman transforms on the skeleton at most
  /// skinning weights fall to 0 at this distance along the skeleton from a
  /// vertex's own node, in units of the surface's diameter
  double blend_radius = 0.05;
  double arap_anchor = 0.1;   ///< pull to the skinned positions, per unit of graph degree
  int arap_iterations = 100;  ///< ARAP refinement steps at most (0: skinning alone)
};

struct ScfResult {
  Eigen::MatrixX3d positions;        ///< canonical positions of every graph vertex, zero mean
  Eigen::MatrixX3d skinned;          ///< the same before the ARAP refinement, zero mean
  CurveSkeleton skeleton;            ///< the rest skeleton
  UnbentSkeleton unbent;             ///< its straightened nodes and the MDS record
  Eigen::MatrixX3d canonical_nodes;  ///< the straightened nodes where `positions` has them
};

/// Checks the option values. @throws UsageError naming the scf.* key
void validate_scf_options(const ScfOptions& options);

/// The SCF canonical form of a mesh.
/// @param graph the edge graph (tet mesh, or the surface when it has no tets)
/// @param P     rest positions of every graph vertex; its first rows are the surface's
/// @param num_surface_vertices the surface's vertices are P's first rows
/// @param F     the surface's triangles (indices into those rows)
/// @param T     the tets over P, or none: when the surface's repair leaves
///              vertices out of the contraction (curve_skeleton), the boundary
///              of the tets is contracted too, and the skeleton leaving fewer
///              out is kept (the tetrahedralization closes seams the repair
///              cannot, e.g. the davids' neck at 2k)
/// @throws as curve_skeleton and unbend_skeleton; UsageError for bad options or sizes
ScfResult scf(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int num_surface_vertices,
              const Eigen::MatrixX3i& F, const Eigen::MatrixX4i& T, const ScfOptions& options);

}  // namespace unfold
