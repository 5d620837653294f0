// Reads a tetrahedral mesh someone else made (TetWild, Gmsh, a simulation) or
// that --rest_tet_output wrote: VTK XML (.vtu, ASCII), TetGen (.node with its
// .ele), Gmsh (.msh, ASCII versions 2 and 4) or MEDIT (.mesh, ASCII).
#pragma once

#include <Eigen/Core>
#include <string>

namespace unfold {

/// A tet mesh as read: vertices and tetrahedra, in the file's order.
struct TetMeshData {
  Eigen::MatrixX3d V;
  Eigen::MatrixX4i T;  ///< 0-based rows of V
  /// a .vtu's point array "unfolded" (3 components), as --rest_tet_output
  /// writes it for the unfolded shape's tets: where they were made; else empty
  Eigen::MatrixX3d unfolded;
};

/// Throws InputError unless path ends in .vtu, .node, .msh or .mesh.
void check_tet_input_format(const std::string& path);

/// Reads the vertices and the tetrahedra of a tet mesh file; other elements
/// (a .msh's or .mesh's boundary triangles, edges, points) are skipped, other
/// cells of a .vtu refused.
/// @throws InputError naming the file for an unsupported format (binary .vtu
///         or .msh included), a malformed or truncated file, an index out of
///         range, or no tetrahedra, or an "unfolded" array of the wrong size
TetMeshData read_tet_mesh(const std::string& path);

}  // namespace unfold
