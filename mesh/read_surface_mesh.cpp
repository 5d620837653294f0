#include "mesh/read_surface_mesh.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "mesh/mesh_format.h"
#include "mesh/silence_openmesh.h"

// Text formats (OFF, OBJ, ASCII PLY) are parsed here because OpenMesh 9's
// readers pass every position to the importer as float, losing the digits the
// file holds, and its OFF reader silently repeats the last face of a truncated
// file. Binary OFF/PLY and STL store floats anyway and go through OpenMesh's
// IO layer with an importer that keeps the faces as given.

namespace unfold {
namespace {

using Tokens = std::vector<std::string_view>;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("cannot read '" + path + "': " + what);
}

// Accepts a whole token only; from_chars also handles "nan" and "inf".
template <typename T>
bool parse_number(std::string_view s, T* value) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto result = std::from_chars(s.data(), s.data() + s.size(), *value);
  return result.ec == std::errc() && result.ptr == s.data() + s.size();
}

bool parse_index(std::string_view s, int* value) {
  long long v;
  if (!parse_number(s, &v) || v < INT_MIN || v > INT_MAX) return false;
  *value = int(v);
  return true;
}

// Rejects headers that declare more elements than the file can hold before
// anything is allocated or looped over (a corrupt count must not hang us).
void check_declared_size(const std::string& path, const std::string& declared, double min_bytes,
                         std::uintmax_t file_size) {
  if (min_bytes > double(file_size))
    fail(path, "the header declares " + declared + ", more than its " + std::to_string(file_size) +
                   " bytes can hold (truncated or corrupt file)");
}

// The content lines of a text file, split into whitespace-separated tokens;
// blank lines and '#' comments are skipped.
class TextLines {
 public:
  TextLines(std::istream& in, const std::string& path) : in_(in), path_(path) {}

  /// Tokens of the next content line (valid until the next call); false at end of file.
  bool next(Tokens* tokens) {
    while (std::getline(in_, text_)) {
      ++line_;
      tokens->clear();
      const size_t end = std::min(text_.find('#'), text_.size());
      size_t i = 0;
      while (i < end) {
        while (i < end && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
        const size_t start = i;
        while (i < end && !std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
        if (i > start) tokens->emplace_back(text_.data() + start, i - start);
      }
      if (!tokens->empty()) return true;
    }
    return false;
  }

  /// The whole current line, comments included.
  const std::string& text() const { return text_; }

  [[noreturn]] void fail(const std::string& what) const {
    unfold::fail(path_, "line " + std::to_string(line_) + ": " + what);
  }

 private:
  std::istream& in_;
  const std::string& path_;
  std::string text_;
  int line_ = 0;
};

// Records positions and faces exactly as the OpenMesh reader reports them: no
// halfedge structure, so faces on non-manifold edges are kept. Everything
// else a reader may offer (normals, colours, texture coordinates) is ignored.
class RawImporter : public OpenMesh::IO::BaseImporter {
 public:
  std::vector<double> coords;  // x y z per vertex
  std::vector<std::vector<int>> faces;

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    coords.insert(coords.end(), {p[0], p[1], p[2]});
    return OpenMesh::VertexHandle(int(n_vertices()) - 1);
  }
  OpenMesh::VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3d(0, 0, 0)); }
  void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.idx() < 0 || size_t(v.idx()) >= n_vertices()) return;
    std::copy(p.data(), p.data() + 3, coords.begin() + 3 * v.idx());
  }
  OpenMesh::FaceHandle add_face(const VHandles& vertices) override {
    std::vector<int> face;
    face.reserve(vertices.size());
    for (const auto& v : vertices) face.push_back(v.idx());
    faces.push_back(std::move(face));
    return OpenMesh::FaceHandle(int(faces.size()) - 1);
  }
  size_t n_vertices() const override { return coords.size() / 3; }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }

  // Halfedge-level construction (only the .om reader uses it) and attributes.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
};

SurfaceMesh to_mesh(const std::vector<double>& coords, std::vector<std::vector<int>> faces) {
  SurfaceMesh mesh;
  mesh.V = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      coords.data(), Eigen::Index(coords.size() / 3), 3);
  mesh.faces = std::move(faces);
  return mesh;
}

// Reads a binary file with OpenMesh; a reader that delivers fewer elements
// than the header declared met a truncated file.
SurfaceMesh read_with_openmesh(const std::string& path, long long declared_vertices,
                               long long declared_faces) {
  RawImporter importer;
  OpenMesh::IO::Options options;
  bool ok;
  {
    SilenceOpenMesh quiet;
    ok = OpenMesh::IO::IOManager().read(path, importer, options);
  }
  if (!ok) fail(path, "OpenMesh cannot parse the file (corrupt or truncated)");
  if (declared_vertices >= 0 && (long long)importer.n_vertices() != declared_vertices)
    fail(path, "truncated: " + std::to_string(importer.n_vertices()) + " of " +
                   std::to_string(declared_vertices) + " vertices");
  if (declared_faces >= 0 && (long long)importer.n_faces() != declared_faces)
    fail(path, "truncated: " + std::to_string(importer.n_faces()) + " of " +
                   std::to_string(declared_faces) + " faces");
  return to_mesh(importer.coords, std::move(importer.faces));
}

// Walks the face records of a binary OFF ("k i1..ik", int32 each) after the
// vertices, so that a corrupt k is refused here: OpenMesh would allocate
// whatever it says (gigabytes, found by fuzzing).
void check_binary_off_faces(std::istream& in, const std::string& path, int32_t vertices,
                            int32_t faces) {
  in.seekg(std::streamoff(12) * vertices, std::ios::cur);
  const std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t at = 0;
  for (int32_t f = 0; f < faces; ++f) {
    int32_t k;
    if (!in || at + 4 > rest.size())
      fail(path, "truncated: " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
    std::memcpy(&k, rest.data() + at, 4);
    if (k < 1 || size_t(k) > (rest.size() - at - 4) / 4)
      fail(path, "bad vertex count " + std::to_string(k) + " for face " + std::to_string(f) +
                     " (truncated or corrupt file)");
    at += 4 + 4 * size_t(k);
  }
}

// OFF: "[ST][C][N]OFF [BINARY]", counts "nv nf ne", one vertex per line (x y z
// first, then optional normal/colour values), one face per line ("k i1..ik",
// then an optional colour).
SurfaceMesh read_off(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  TextLines lines(in, path);
  Tokens t;
  if (!lines.next(&t)) fail(path, "the file is empty");
  std::string key(t[0]);
  if (key.find_first_of("4n") != std::string::npos)
    lines.fail("OFF variant '" + key + "' is not supported (only 3D positions)");
  // Letters only: OpenMesh, which reads binary OFF, parses the header again
  // and reads other counts after stray bytes (found by fuzzing).
  if (key.size() < 3 || key.compare(key.size() - 3, 3, "OFF") != 0 ||
      key.find_first_not_of("STCNOF") != std::string::npos) {
    for (char& c : key)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    lines.fail("no OFF header (found '" + key + "')");
  }
  if (t.size() > 1 && t[1] == "BINARY") {
    int32_t counts[3];  // host byte order, as OpenMesh reads and writes it
    // Exactly as OpenMesh expects it, or it reads the body as text (fuzzing).
    const std::string& header = lines.text();
    if ((header != key + " BINARY" && header != key + " BINARY\r") ||
        !in.read(reinterpret_cast<char*>(counts), sizeof(counts)) || counts[0] < 1 || counts[1] < 1)
      fail(path, "bad header or vertex and face counts in the binary OFF header");
    check_declared_size(
        path, std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) + " faces",
        12.0 * counts[0] + 16.0 * counts[1], file_size);
    check_binary_off_faces(in, path, counts[0], counts[1]);
    return read_with_openmesh(path, counts[0], counts[1]);
  }
  t.erase(t.begin());
  if (t.empty() && !lines.next(&t)) fail(path, "missing vertex and face counts");
  long long nv, nf;
  if (t.size() < 2 || !parse_number(t[0], &nv) || !parse_number(t[1], &nf) || nv < 0 || nf < 0 ||
      nv > INT_MAX || nf > INT_MAX)
    lines.fail("bad vertex and face counts");
  // Smallest possible text: "0 0 0\n" per vertex, "3 0 0 0\n" per face.
  check_declared_size(path, std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces",
                      6.0 * nv + 8.0 * nf, file_size);

  std::vector<double> coords(3 * static_cast<size_t>(nv));
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next(&t))
      fail(path, "truncated: " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (t.size() < 3 || !parse_number(t[0], &coords[3 * i]) ||
        !parse_number(t[1], &coords[3 * i + 1]) || !parse_number(t[2], &coords[3 * i + 2]))
      lines.fail("bad coordinates for vertex " + std::to_string(i));
  }
  std::vector<std::vector<int>> faces(static_cast<size_t>(nf));
  for (long long f = 0; f < nf; ++f) {
    if (!lines.next(&t))
      fail(path, "truncated: " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long k;
    if (!parse_number(t[0], &k) || k < 0 || k >= (long long)t.size())
      lines.fail("bad vertex list for face " + std::to_string(f));
    faces[f].resize(size_t(k));
    for (long long j = 0; j < k; ++j)
      if (!parse_index(t[j + 1], &faces[f][j]))
        lines.fail("bad vertex index '" + std::string(t[j + 1]) + "' in face " + std::to_string(f));
  }
  return to_mesh(coords, std::move(faces));
}

// OBJ: "v x y z" and "f a b c ..." where each corner is "i", "i/t", "i//n" or
// "i/t/n" with 1-based or negative (relative) i. Other records (vt, vn, g, o,
// s, usemtl, l, ...) carry nothing unfold needs.
SurfaceMesh read_obj(std::istream& in, const std::string& path) {
  TextLines lines(in, path);
  Tokens t;
  std::vector<double> coords;
  std::vector<std::vector<int>> faces;
  while (lines.next(&t)) {
    if (t[0] == "v") {
      double p[3];
      if (t.size() < 4 || !parse_number(t[1], &p[0]) || !parse_number(t[2], &p[1]) ||
          !parse_number(t[3], &p[2]))
        lines.fail("bad vertex " + std::to_string(coords.size() / 3 + 1));
      coords.insert(coords.end(), p, p + 3);
    } else if (t[0] == "f") {
      std::vector<int> face;
      for (size_t j = 1; j < t.size(); ++j) {
        long long i;
        if (!parse_number(t[j].substr(0, t[j].find('/')), &i) || i == 0)
          lines.fail("bad vertex reference '" + std::string(t[j]) + "'");
        i = i > 0 ? i - 1 : (long long)(coords.size() / 3) + i;
        if (i < INT_MIN || i > INT_MAX) lines.fail("vertex reference out of range");
        face.push_back(int(i));
      }
      faces.push_back(std::move(face));
    }
  }
  return to_mesh(coords, std::move(faces));
}

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
      fail(path, "the PLY vertex element lacks an x, y or z property");
    for (long long i = 0; i < e.count; ++i) {
      if (!lines.next(&t))
        fail(path, "truncated: " + std::to_string(i) + " of " + std::to_string(e.count) + " " +
                       e.name + " elements");
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
  return to_mesh(coords, std::move(faces));
}

// PLY: header lines up to "end_header", then ASCII records or binary data.
SurfaceMesh read_ply(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  TextLines lines(in, path);
  Tokens t;
  if (!lines.next(&t) || t[0] != "ply") fail(path, "no PLY header (first line is not 'ply')");
  std::string format;
  std::vector<PlyElement> elements;
  for (;;) {
    if (!lines.next(&t)) fail(path, "the PLY header has no end_header");
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
      fail(path, "the PLY element '" + e.name + "' has " + std::to_string(e.count) +
                     " records but no properties");
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    fail(path, "unknown PLY format '" + format + "'");
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

// STL: binary when the size matches the triangle count at byte 80 (the rule
// OpenMesh applies too), else ASCII, which must be complete ("endsolid").
SurfaceMesh read_stl(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  char header[84] = {};
  in.read(header, sizeof(header));
  uint32_t triangles;
  std::memcpy(&triangles, header + 80, sizeof(triangles));
  const bool binary = file_size >= 84 && 84 + 50 * std::uintmax_t(triangles) == file_size;
  if (!binary) {
    if (std::string_view(header, 5) != "solid")
      fail(path, "neither ASCII STL (no 'solid' header) nor binary STL (size does not match " +
                     std::to_string(triangles) + " triangles)");
    // The closing keyword sits at the end; search the tail only.
    const std::uintmax_t tail = std::min<std::uintmax_t>(file_size, 1024);
    std::string end(tail, '\0');
    in.clear();
    in.seekg(std::streamoff(file_size - tail));
    in.read(end.data(), std::streamsize(tail));
    if (end.find("endsolid") == std::string::npos) fail(path, "truncated ASCII STL (no endsolid)");
  }
  return read_with_openmesh(path, -1, binary ? (long long)triangles : -1);
}

}  // namespace

SurfaceMesh read_surface_mesh(const std::string& path) {
  const std::optional<MeshFormat> format = mesh_format_from_path(path);
  if (!format) fail(path, describe_unsupported_extension(path));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::strerror(errno));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail(path, ec.message());

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
  if (mesh.V.rows() == 0) fail(path, "the mesh has no vertices");
  if (mesh.faces.empty()) fail(path, "the mesh has no faces");
  return mesh;
}

}  // namespace unfold
