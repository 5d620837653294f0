// The surface mesh file formats unfold reads and writes, named by extension.
#pragma once

#include <optional>
#include <string>

namespace unfold {

enum class MeshFormat { kOff, kObj, kPly, kStl };

/// The format named by the extension of `path` (case-insensitive), or
/// std::nullopt for an unknown or missing extension. Throws nothing.
std::optional<MeshFormat> mesh_format_from_path(const std::string& path);

/// Error-message fragment for a path whose extension names no format, e.g.
/// "unsupported extension '.xyz' (use .off, .obj, .ply or .stl)". Throws nothing.
std::string describe_unsupported_extension(const std::string& path);

}  // namespace unfold
