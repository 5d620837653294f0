// How far a point-to-point map is from the true correspondence (the protocol
// of Kim et al. 2011 and the BCICP dataset): per template point, the geodesic
// distance on the target between its image and its true point, over the
// square root of the target's area.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// Shortest-path distances along the edges of a target surface (metrics/
/// graph_geodesics.h; an upper bound of the true geodesic distance within a few
/// percent on a regular mesh) from a set of vertices, divided by sqrt(area).
struct GeodesicTable {
  std::vector<int> row_of_vertex;  ///< per vertex of the target, its row, or -1
  Eigen::MatrixXf rows;            ///< one row per source vertex, one column per vertex
};

/// @param V, F the target surface (n x 3, triangles), connected
/// @param sources the vertices to measure from (repeats allowed)
/// @throws UsageError for a source out of range; InputError for no area
GeodesicTable geodesic_table(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                             const std::vector<int>& sources);

/// Per template point k, the normalised geodesic distance on the target
/// between map(source_points(k)) and target_points(k); with a second truth
/// (`mirrored_points`, e.g. a .sym.vts), the smaller of the two distances
/// (flip-forgiving).
/// @param table geodesic_table of the target from (at least) every vertex of
///        target_points and mirrored_points
/// @param map one target vertex per source vertex
/// @param source_points, target_points zero-based template ids (read_vts), equal sizes
/// @param mirrored_points empty, or as target_points
/// @throws UsageError on sizes that differ, ids out of range or a truth vertex
///         without a row in `table`
Eigen::VectorXd correspondence_errors(const GeodesicTable& table, const Eigen::VectorXi& map,
                                      const Eigen::VectorXi& source_points,
                                      const Eigen::VectorXi& target_points,
                                      const Eigen::VectorXi& mirrored_points = {});

}  // namespace unfold
