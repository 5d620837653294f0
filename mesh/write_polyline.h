// A graph of line segments (a curve skeleton) as a file ParaView or MeshLab
// opens: legacy VTK POLYDATA lines (.vtk) or ASCII PLY with an edge element (.ply).
#pragma once

#include <Eigen/Core>
#include <string>

namespace unfold {

/// Checks that `path` ends in .vtk or .ply. @throws OutputError naming the path
void check_polyline_format(const std::string& path);

/// Writes the nodes and the segments between them, atomically (core/atomic_file.h).
/// @param edges node index pairs, each in [0, nodes.rows())
/// @throws OutputError for an unsupported extension, an edge naming a missing
///         node, or a failed write
void write_polyline(const std::string& path, const Eigen::MatrixX3d& nodes,
                    const Eigen::MatrixX2i& edges);

}  // namespace unfold
