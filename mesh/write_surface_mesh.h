// Writes a surface mesh with every face kept (also non-manifold ones) and
// positions in full double precision.
#pragma once

#include <string>

#include "mesh/mesh_format.h"
#include "mesh/surface_mesh.h"

namespace unfold {

/// Writes `mesh` atomically (see write_file_atomically) in the format named by
/// the extension of `path` (case-insensitive): ASCII .off, .obj or .ply with
/// polygons as given and 17 significant digits, or binary .stl with the faces
/// fan-triangulated (float precision, as STL stores).
/// @param path destination; its directory must exist.
/// @param mesh faces must refer to existing vertices.
/// @throws OutputError naming `path` for an unsupported extension or a face
///         index out of range (both detected before anything is written), or
///         when writing fails.
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh);

/// The format write_surface_mesh would use for `path`, so callers can refuse a
/// bad output name before doing any work.
/// @throws OutputError naming `path` for an unsupported extension
MeshFormat check_surface_mesh_format(const std::string& path);

}  // namespace unfold
