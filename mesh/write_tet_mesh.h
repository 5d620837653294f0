// Writes a tetrahedral mesh for viewers: VTK XML (.vtu, ParaView) or TetGen's
// .node/.ele pair.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace unfold {

/// Throws OutputError unless path is empty or ends in .vtu or .node.
void check_tet_mesh_format(const std::string& path);

/// Named scalar fields for viewers: one value per vertex or per tet.
struct TetMeshFields {
  std::vector<std::pair<std::string, Eigen::VectorXd>> per_vertex;
  std::vector<std::pair<std::string, Eigen::VectorXd>> per_tet;
  /// 3-vectors per vertex (e.g. "unfolded": where the tets were made)
  std::vector<std::pair<std::string, Eigen::MatrixX3d>> per_vertex_vectors;
};

/// Writes vertices V and tetrahedra T. For "x.node" also writes "x.ele".
/// @param fields written as VTU PointData / CellData (ignored for .node, which has no names)
/// @throws UsageError if a field's size is not V.rows() (per vertex) or T.rows() (per tet)
/// @throws OutputError for an unsupported extension or a failed write (no partial file remains)
void write_tet_mesh(const std::string& path, const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T,
                    const TetMeshFields& fields = {});

}  // namespace unfold
