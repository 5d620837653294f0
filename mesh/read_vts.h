// Correspondences given beside a mesh: a .vts file (as in the FAUST and SHREC
// remeshings of the BCICP dataset) holds one one-based vertex id per line, one
// line per point of a common template, so that row k of every pose's file is
// the same body point even when the poses are meshed differently.
#pragma once

#include <Eigen/Core>
#include <string>

namespace unfold {

/// The .vts file beside a mesh: same directory and stem ("d/a.off" -> "d/a.vts").
std::string vts_path(const std::string& mesh_path);

/// Reads a .vts file: one one-based vertex id per content line (blank lines
/// and '#' comments skipped).
/// @param vertex_count the mesh's vertex count: every id must be in [1, vertex_count]
/// @param expected_rows the number of ids the file must hold; -1: any number >= 1
/// @return the zero-based vertex ids, in file order (an id may repeat: two
///         template points can fall on one vertex of a coarse mesh)
/// @throws InputError naming the file (and the line) if it cannot be read,
///         holds no id, a line is not one integer, an id is out of range, or
///         the number of ids differs from expected_rows
Eigen::VectorXi read_vts(const std::string& path, int vertex_count, int expected_rows = -1);

}  // namespace unfold
