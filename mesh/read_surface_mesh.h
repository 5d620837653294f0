// Reads a surface mesh file (.off .obj .ply .stl) into a SurfaceMesh with the
// faces exactly as stored, so that non-manifold faces survive for checking.
#pragma once

#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Reads vertex positions (double precision for text formats) and faces as
/// given (polygons kept, indices not validated: see check_surface_mesh).
/// Formats: ASCII/binary OFF, OBJ, ASCII/binary PLY, ASCII/binary STL; the
/// extension picks the format, case-insensitively.
/// @param path file to read.
/// @throws InputError (one line, naming `path`) if the file is missing or
///         unreadable, the extension is unsupported, the content cannot be
///         parsed or is truncated, or the mesh has no vertices or no faces.
SurfaceMesh read_surface_mesh(const std::string& path);

}  // namespace unfold
