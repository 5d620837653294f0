// Local damage of a canonical form: how far its surface edges are stretched or
// crushed against the input's, once the form is scaled to the input's area.
// Mean measures (E_rig, the edge ratio) hide a needle or a crushed head; this
// looks at the tail of the per-edge ratios (issue 44).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// An edge is damaged when its ratio lies outside [1/kDamagedEdgeRatio, kDamagedEdgeRatio].
constexpr double kDamagedEdgeRatio = 3.0;

/// The damage measure of one surface in two positions (see surface_damage()).
/// With no measured edge (edges == 0) every figure keeps its default.
struct SurfaceDamage {
  /// sqrt(area(input) / area(canonical)): canonical lengths are multiplied by it
  double scale = 1;
  int edges = 0;                     ///< unique surface edges measured (input length > 0)
  int zero_length_edges = 0;         ///< unique edges of zero input length, skipped
  int damaged_edges = 0;             ///< measured edges with r outside [1/bound, bound]
  double damaged_edges_percent = 0;  ///< 100 * damaged_edges / edges, in [0, 100]
  /// the 99.9th percentile of r, nearest rank: r_(k) of the ratios sorted
  /// ascending, k = ceil(0.999 * edges) (the largest r up to 1,000 edges)
  double ratio_p999 = 1;
  double ratio_max = 1;  ///< the largest r: the most stretched edge
  double ratio_min = 1;  ///< the smallest r: the most crushed edge (0: collapsed)
  /// per vertex: the largest |ln r| of its measured edges (0: none, or all
  /// intact); ln 3 = 1.0986 is the damage bound; a collapsed edge (r = 0)
  /// counts as |ln DBL_MIN| = 708.4, so that every value is finite
  Eigen::VectorXd per_vertex;
  /// per vertex: the ratio r of that edge (> 1 stretched, < 1 crushed; 1: none)
  Eigen::VectorXd per_vertex_ratio;
};

/// The damage of a deformed surface against its rest shape, over its unique
/// edges (each pair of vertices consecutive in a face, the last one joined to
/// the first; an edge shared by faces counts once). Each edge e = (i, j) of
/// nonzero input length has the ratio
///   r_e = s |out_i - out_j| / |in_i - in_j|,  s = sqrt(area(in) / area(out)),
/// areas over the fan-triangulated faces: r_e = 1 for every edge when out is a
/// similarity transform (rotation, uniform scale, translation) of in. Edges of
/// zero input length are skipped and counted. Deterministic, O(E log E).
/// @param V_in   rest positions (n x 3), e.g. the surface unfolded
/// @param V_out  deformed positions (n x 3), e.g. its canonical form; same rows
/// @param faces  polygons (3 or more vertex indices each) into both
/// @param bound  an edge is damaged when r_e < 1 / bound or r_e > bound; > 1
/// @throws UsageError if V_in and V_out differ in rows, or bound <= 1 (or NaN)
/// @throws InputError if there is no face, a face has fewer than 3 vertices or
///         an index outside [0, n), a coordinate of V_in is not finite, or
///         V_in's faces have zero area
/// @throws NumericalError if a coordinate of V_out is not finite or V_out's
///         faces have zero area
SurfaceDamage surface_damage(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                             const std::vector<std::vector<int>>& faces,
                             double bound = kDamagedEdgeRatio);

/// The same with one face per row of F (m x k, k >= 3; e.g. triangles).
SurfaceDamage surface_damage(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                             const Eigen::MatrixXi& F, double bound = kDamagedEdgeRatio);

}  // namespace unfold
