// Writes a tetrahedral mesh for viewers: VTK XML (.vtu, ParaView) or TetGen's
// .node/.ele pair.
#pragma once

#include <Eigen/Core>
#include <string>

namespace unfold {

/// Throws OutputError unless path is empty or ends in .vtu or .node.
void check_tet_mesh_format(const std::string& path);

/// Writes vertices V and tetrahedra T. For "x.node" also writes "x.ele".
/// @throws OutputError for an unsupported extension or a failed write (no partial file remains)
void write_tet_mesh(const std::string& path, const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T);

}  // namespace unfold
