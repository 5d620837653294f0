#include "mesh/read_ply.h"

#include <algorithm>
#include <climits>
#include <string_view>
#include <vector>

#include "mesh/read_with_openmesh.h"
#include "mesh/text_lines.h"

namespace unfold {
namespace {

struct PlyProperty {
  std::string name;
  std::string type;        // scalar type, or item type of a list
  std::string count_type;  // empty for a scalar property
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

int ply_type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

long long declared_count(const std::vector<PlyElement>& elements, const std::string& name) {
  for (const auto& e : elements)
    if (e.name == name) return e.count;
  return 0;
}

// Parses the element records of an ASCII PLY body, one record per line.
SurfaceMesh read_ply_text(TextLines& lines, const std::vector<PlyElement>& elements,
                          const std::string& path) {
  std::vector<double> coords;
  std::vector<std::vector<int>> faces;
  Tokens t;
  for (const auto& e : elements) {
    // Which property feeds which output: coordinate 0-2, or 3 for the face list.
    std::vector<int> role(e.properties.size(), -1);
    for (size_t p = 0; p < e.properties.size(); ++p) {
      const auto& prop = e.properties[p];
      if (e.name == "vertex" && prop.count_type.empty() && prop.name.size() == 1 &&
          prop.name[0] >= 'x' && prop.name[0] <= 'z')
        role[p] = prop.name[0] - 'x';
      if (e.name == "face" && !prop.count_type.empty() &&
          (prop.name == "vertex_indices" || prop.name == "vertex_index"))
        role[p] = 3;
    }
    if (e.name == "vertex" &&
        std::count_if(role.begin(), role.end(), [](int r) { return r >= 0; }) != 3)
      fail_reading(path, "the PLY vertex element lacks an x, y or z property");
    for (long long i = 0; i < e.count; ++i) {
      if (!lines.next(&t))
        fail_reading(path, "truncated: " + std::to_string(i) + " of " + std::to_string(e.count) +
                               " " + e.name + " elements");
      size_t pos = 0;
      const auto token = [&]() {
        if (pos >= t.size()) lines.fail("too few values for " + e.name + " " + std::to_string(i));
        return t[pos++];
      };
      double point[3] = {0, 0, 0};
      for (size_t p = 0; p < e.properties.size(); ++p) {
        if (e.properties[p].count_type.empty()) {
          const std::string_view value = token();
          if (role[p] >= 0 && !parse_number(value, &point[role[p]]))
            lines.fail("bad coordinate '" + std::string(value) + "' for vertex " +
                       std::to_string(i));
          continue;
        }
        long long k;
        if (!parse_number(token(), &k) || k < 0)
          lines.fail("bad list length in " + e.name + " " + std::to_string(i));
        std::vector<int> face;
        for (long long j = 0; j < k; ++j) {
          const std::string_view value = token();
          if (role[p] != 3) continue;
          face.emplace_back();
          if (!parse_index(value, &face.back()))
            lines.fail("bad vertex index '" + std::string(value) + "' in face " +
                       std::to_string(i));
        }
        if (role[p] == 3) faces.push_back(std::move(face));
      }
      if (e.name == "vertex") coords.insert(coords.end(), point, point + 3);
    }
  }
  return surface_mesh_from_rows(coords, std::move(faces));
}

}  // namespace

SurfaceMesh read_ply(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  TextLines lines(in, path);
  Tokens t;
  if (!lines.next(&t) || t[0] != "ply")
    fail_reading(path, "no PLY header (first line is not 'ply')");
  std::string format;
  std::vector<PlyElement> elements;
  for (;;) {
    if (!lines.next(&t)) fail_reading(path, "the PLY header has no end_header");
    // OpenMesh parses the header again, has no '#' comments and loops forever
    // on some non-text bytes (found by fuzzing): the header must be plain text
    // that both read alike.
    if (t[0] != "comment" && t[0] != "obj_info" && lines.text().find('#') != std::string::npos)
      lines.fail("'#' in the PLY header");
    if (t[0] == "end_header") break;
    for (const std::string_view token : t)
      for (const char c : token)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
          lines.fail("non-text byte in the PLY header");
    if (t[0] == "format" && t.size() == 3) {
      if (t[2] != "1.0") lines.fail("unsupported PLY version '" + std::string(t[2]) + "'");
      format = t[1];
    } else if (t[0] == "element" && t.size() == 3) {
      elements.push_back({std::string(t[1]), 0, {}});
      if (!parse_number(t[2], &elements.back().count) || elements.back().count < 0 ||
          elements.back().count > INT_MAX)
        lines.fail("bad element count '" + std::string(t[2]) + "'");
    } else if (t[0] == "property" && !elements.empty() && t.size() == 3 &&
               ply_type_size(std::string(t[1])) > 0) {
      elements.back().properties.push_back({std::string(t[2]), std::string(t[1]), ""});
    } else if (t[0] == "property" && !elements.empty() && t.size() == 5 && t[1] == "list" &&
               ply_type_size(std::string(t[2])) > 0 && ply_type_size(std::string(t[3])) > 0) {
      elements.back().properties.push_back(
          {std::string(t[4]), std::string(t[3]), std::string(t[2])});
    } else if (t[0] != "comment" && t[0] != "obj_info") {
      lines.fail("unexpected PLY header line starting with '" + std::string(t[0]) + "'");
    }
  }
  // An element without properties takes no bytes, so the size check below
  // cannot bound its count (OpenMesh then adds them all: found by fuzzing).
  for (const auto& e : elements)
    if (e.count > 0 && e.properties.empty())
      fail_reading(path, "the PLY element '" + e.name + "' has " + std::to_string(e.count) +
                             " records but no properties");
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    fail_reading(path, "unknown PLY format '" + format + "'");
  // Smallest record: 2 characters per value in ASCII, the packed sizes in binary
  // (lists counted as empty).
  double min_bytes = 0;
  for (const auto& e : elements)
    for (const auto& p : e.properties)
      min_bytes += double(e.count) *
                   (ascii ? 2 : ply_type_size(p.count_type.empty() ? p.type : p.count_type));
  check_declared_size(path,
                      std::to_string(declared_count(elements, "vertex")) + " vertices and " +
                          std::to_string(declared_count(elements, "face")) + " faces",
                      min_bytes, file_size);
  if (ascii) return read_ply_text(lines, elements, path);
  return read_with_openmesh(path, declared_count(elements, "vertex"),
                            declared_count(elements, "face"));
}

}  // namespace unfold
