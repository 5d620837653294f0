// The view sphere of CM-BOF (Lian et al., "CM-BOF: visual similarity-based 3D
// shape retrieval using Clock Matching and Bag-of-Features", Machine Vision
// and Applications 2013): view directions at the vertices of a geodesic sphere
// made by subdividing a regular octahedron, and the 24 rotations of the
// octahedron as permutations of those views (the "clock" over which two
// shapes' views are matched, the ambiguity a pose normalisation leaves).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// Unit view directions: the 6 vertices of the octahedron (±x, ±y, ±z), each
/// triangle split into four `subdivisions` times, new vertices pushed onto the
/// sphere; 6, 18, 66, 258 directions for 0, 1, 2, 3 subdivisions.
/// Deterministic order, the octahedron's vertices first.
/// @throws UsageError for subdivisions outside [0, 3] (the view counts CM-BOF
///         studies)
Eigen::MatrixX3d view_sphere_directions(int subdivisions);

/// For each of the 24 rotations R of the octahedron (cube_rotations()), the
/// permutation p of the views with directions.row(p[v]) = R directions.row(v);
/// the identity first.
/// @pre directions from view_sphere_directions
/// @throws UsageError if a rotated direction is not a view (not such a set)
std::vector<std::vector<int>> view_sphere_rotations(const Eigen::MatrixX3d& directions);

}  // namespace unfold
