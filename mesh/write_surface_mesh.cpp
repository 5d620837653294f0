#include "mesh/write_surface_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <locale>
#include <ostream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "mesh/mesh_format.h"

namespace unfold {
namespace {

// The header's counts without digit grouping, whatever the process locale is
// (the rows go through std::to_chars, which ignores locales).
void prepare_text(std::ostream& out) { out.imbue(std::locale::classic()); }

// Lines are formatted into a buffer by std::to_chars (the shortest text that
// reads back as the same double, locale-independent) and written in large
// blocks: several times faster than the stream's formatting.
class LineBuffer {
 public:
  explicit LineBuffer(std::ostream& out) : out_(out) {}
  ~LineBuffer() { flush(); }
  template <typename T>
  void number(T value) {
    reserve(32);
    at_ = std::to_chars(at_, end(), value).ptr;
  }
  void text(const char* s) {
    const size_t n = std::strlen(s);
    reserve(n);
    at_ = std::copy(s, s + n, at_);
  }
  void put(char c) {
    reserve(1);
    *at_++ = c;
  }

 private:
  char* end() { return data_.data() + data_.size(); }
  void reserve(size_t n) {
    if (size_t(end() - at_) < n) flush();
  }
  void flush() {
    out_.write(data_.data(), at_ - data_.data());
    at_ = data_.data();
  }
  std::ostream& out_;
  std::array<char, 1 << 16> data_;
  char* at_ = data_.data();
};

void write_vertex_rows(std::ostream& out, const SurfaceMesh& mesh, const char* prefix) {
  LineBuffer line(out);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i) {
    line.text(prefix);
    for (int k = 0; k < 3; ++k) {
      line.number(mesh.V(i, k));
      line.put(k < 2 ? ' ' : '\n');
    }
  }
}

// "k i1 ... ik" per face (OFF and PLY), or "f i1+1 ... ik+1" (OBJ, 1-based).
void write_faces(std::ostream& out, const SurfaceMesh& mesh, bool obj) {
  LineBuffer line(out);
  for (const auto& face : mesh.faces) {
    if (obj)
      line.put('f');
    else
      line.number(face.size());
    for (int v : face) {
      line.put(' ');
      line.number(obj ? v + 1 : v);
    }
    line.put('\n');
  }
}

void write_off(std::ostream& out, const SurfaceMesh& mesh) {
  prepare_text(out);
  out << "OFF\n" << mesh.V.rows() << ' ' << mesh.faces.size() << " 0\n";
  write_vertex_rows(out, mesh, "");
  write_faces(out, mesh, false);
}

void write_obj(std::ostream& out, const SurfaceMesh& mesh) {
  prepare_text(out);
  out << "# written by unfold\n";
  write_vertex_rows(out, mesh, "v ");
  write_faces(out, mesh, true);
}

void write_ply(std::ostream& out, const SurfaceMesh& mesh) {
  prepare_text(out);
  size_t largest_face = 0;
  for (const auto& face : mesh.faces) largest_face = std::max(largest_face, face.size());
  out << "ply\nformat ascii 1.0\ncomment written by unfold\n"
      << "element vertex " << mesh.V.rows() << '\n'
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.faces.size()
      << '\n'
      // uchar counts are what every reader expects; larger polygons need int.
      << "property list " << (largest_face <= 255 ? "uchar" : "int") << " int vertex_indices\n"
      << "end_header\n";
  write_vertex_rows(out, mesh, "");
  write_faces(out, mesh, false);
}

template <typename T>
void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(value));
}

// Binary STL is little-endian by definition; the bytes are written as the host
// stores them.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "binary STL output assumes little-endian");

void write_stl(std::ostream& out, const SurfaceMesh& mesh, const Eigen::MatrixX3i& triangles) {
  // The header must not start with "solid", which marks ASCII STL.
  char header[80] = "binary STL written by unfold";
  out.write(header, sizeof(header));
  put(out, uint32_t(triangles.rows()));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.V.row(triangles(t, 0)), b = mesh.V.row(triangles(t, 1)),
                          c = mesh.V.row(triangles(t, 2));
    const Eigen::Vector3f normal = (b - a).cross(c - a).normalized().cast<float>();
    for (const Eigen::Vector3f& p :
         {normal, a.cast<float>().eval(), b.cast<float>().eval(), c.cast<float>().eval()})
      for (int k = 0; k < 3; ++k) put(out, p[k]);
    put(out, uint16_t(0));  // attribute byte count
  }
}

}  // namespace

MeshFormat check_surface_mesh_format(const std::string& path) {
  const std::optional<MeshFormat> format = mesh_format_from_path(path);
  if (!format)
    throw OutputError("cannot write '" + path + "': " + describe_unsupported_extension(path));
  return *format;
}

void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh) {
  const auto reject = [&](const std::string& what) {
    throw OutputError("cannot write '" + path + "': " + what);
  };
  const MeshFormat format = check_surface_mesh_format(path);
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= mesh.V.rows())
        reject("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
               " but the mesh has " + std::to_string(mesh.V.rows()) + " vertices");

  switch (format) {
    case MeshFormat::kOff:
      return write_file_atomically(path, [&](std::ostream& out) { write_off(out, mesh); });
    case MeshFormat::kObj:
      return write_file_atomically(path, [&](std::ostream& out) { write_obj(out, mesh); });
    case MeshFormat::kPly:
      return write_file_atomically(path, [&](std::ostream& out) { write_ply(out, mesh); });
    case MeshFormat::kStl: {
      const Eigen::MatrixX3i triangles = triangulate_faces(mesh);
      if (triangles.rows() > Eigen::Index(std::numeric_limits<uint32_t>::max()))
        reject("too many triangles for STL");
      return write_file_atomically(
          path, [&](std::ostream& out) { write_stl(out, mesh, triangles); }, true);
    }
  }
}

}  // namespace unfold
