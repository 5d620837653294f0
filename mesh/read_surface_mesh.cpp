#include "mesh/read_surface_mesh.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "mesh/mesh_format.h"
#include "mesh/read_obj.h"
#include "mesh/read_off.h"
#include "mesh/read_ply.h"
#include "mesh/read_stl.h"
#include "mesh/text_lines.h"

// One reader per format (mesh/read_off.h, read_obj.h, read_ply.h, read_stl.h).
// Text formats (OFF, OBJ, ASCII PLY) are parsed by unfold because OpenMesh 9's
// readers pass every position to the importer as float, losing the digits the
// file holds, and its OFF reader silently repeats the last face of a truncated
// file. Binary OFF/PLY and STL store floats anyway and go through OpenMesh
// (mesh/read_with_openmesh.h).

namespace unfold {

SurfaceMesh read_surface_mesh(const std::string& path) {
  const std::optional<MeshFormat> format = mesh_format_from_path(path);
  if (!format) fail_reading(path, describe_unsupported_extension(path));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail_reading(path, "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_reading(path, std::strerror(errno));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail_reading(path, ec.message());

  SurfaceMesh mesh;
  switch (*format) {
    case MeshFormat::kOff:
      mesh = read_off(in, path, size);
      break;
    case MeshFormat::kObj:
      mesh = read_obj(in, path);
      break;
    case MeshFormat::kPly:
      mesh = read_ply(in, path, size);
      break;
    case MeshFormat::kStl:
      mesh = read_stl(in, path, size);
      break;
  }
  if (mesh.V.rows() == 0) fail_reading(path, "the mesh has no vertices");
  if (mesh.faces.empty()) fail_reading(path, "the mesh has no faces");
  return mesh;
}

}  // namespace unfold
