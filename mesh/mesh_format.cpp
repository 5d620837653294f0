#include "mesh/mesh_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace unfold {
namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

std::optional<MeshFormat> mesh_format_from_path(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext == ".off") return MeshFormat::kOff;
  if (ext == ".obj") return MeshFormat::kObj;
  if (ext == ".ply") return MeshFormat::kPly;
  if (ext == ".stl") return MeshFormat::kStl;
  return std::nullopt;
}

std::string describe_unsupported_extension(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  return (ext.empty() ? std::string("no file extension") : "unsupported extension '" + ext + "'") +
         " (use .off, .obj, .ply or .stl)";
}

}  // namespace unfold
