// The curve skeleton of a closed surface and which skeleton node each surface
// vertex contracted to: CGAL's mean-curvature-flow skeletonization
// (Tagliasacchi et al. 2012, the successor of Au et al. 2008's mesh
// contraction that the SCF baseline uses; docs/baselines.md). CGAL stays
// inside curve_skeleton.cpp: this interface is plain Eigen.
#pragma once

#include <Eigen/Core>

namespace unfold {

struct CurveSkeletonOptions {
  double quality_speed_tradeoff = 0.1;            ///< CGAL's w_H: larger, slower and finer
  double medially_centered_speed_tradeoff = 0.2;  ///< CGAL's w_M: larger, more centred
  int max_iterations = 500;                       ///< contraction steps at most
  /// edges shorter than this times the mesh's diameter (twice the largest
  /// distance from the centroid: unlike CGAL's bounding-box default, the same
  /// for every rotation of the mesh) are collapsed
  double min_edge_length = 0.002;
};

struct CurveSkeleton {
  Eigen::MatrixX3d nodes;          ///< one row per skeleton node
  Eigen::MatrixX2i edges;          ///< bones: node index pairs, first < second
  Eigen::VectorXi node_of_vertex;  ///< per surface vertex, the node it contracted to
  /// surface vertices the contraction did not carry (left out by the repair),
  /// whose node is their nearest carried vertex's
  int num_left_out = 0;
};

/// Gives every vertex without a node (-1 in *node_of_vertex) the node of its
/// nearest vertex that has one.
/// @param V vertex positions, one row per entry of *node_of_vertex
/// @returns how many vertices took another's node
/// @throws NumericalError if no vertex has a node
int assign_nearest_nodes(const Eigen::MatrixX3d& V, Eigen::VectorXi* node_of_vertex);

/// Checks the option values. @throws UsageError naming the scf.* key
void validate_curve_skeleton_options(const CurveSkeletonOptions& options);

/// Contracts the surface (V, F) by mean curvature flow into a curve skeleton.
/// @param V surface vertices
/// @param F triangles of a connected surface; its holes are closed (triangles
///         between each hole's own vertices) before the contraction. A surface
///         that is not a 2-manifold, or whose holes cannot be closed so, is
///         repaired first: oriented as a polygon soup (vertices duplicated
///         where needed), stitched, its holes closed, its largest component
///         kept; the vertices it leaves out take the node of their nearest
///         vertex
/// @throws InputError if the surface has fewer than 8 vertices, several
///         components, or is still open after the repair; NumericalError if
///         the contraction yields no skeleton of at
///         least two nodes (a thin sheet may collapse to a point or a surface)
///         or CGAL fails
/// @throws UsageError for bad options
CurveSkeleton curve_skeleton(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                             const CurveSkeletonOptions& options = {});

}  // namespace unfold
