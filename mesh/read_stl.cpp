#include "mesh/read_stl.h"

#include <algorithm>
#include <cstring>
#include <string_view>

#include "mesh/read_with_openmesh.h"
#include "mesh/text_lines.h"

namespace unfold {

SurfaceMesh read_stl(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  char header[84] = {};
  in.read(header, sizeof(header));
  uint32_t triangles;
  std::memcpy(&triangles, header + 80, sizeof(triangles));
  const bool binary = file_size >= 84 && 84 + 50 * std::uintmax_t(triangles) == file_size;
  if (!binary) {
    if (std::string_view(header, 5) != "solid")
      fail_reading(path,
                   "neither ASCII STL (no 'solid' header) nor binary STL (size does not match " +
                       std::to_string(triangles) + " triangles)");
    // The closing keyword sits at the end; search the tail only.
    const std::uintmax_t tail = std::min<std::uintmax_t>(file_size, 1024);
    std::string end(tail, '\0');
    in.clear();
    in.seekg(std::streamoff(file_size - tail));
    in.read(end.data(), std::streamsize(tail));
    if (end.find("endsolid") == std::string::npos)
      fail_reading(path, "truncated ASCII STL (no endsolid)");
  }
  return read_with_openmesh(path, -1, binary ? (long long)triangles : -1);
}

}  // namespace unfold
