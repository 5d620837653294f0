#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "tests/test_files.h"
#include "tests/test_meshes.h"

namespace unfold {
namespace {

using test::Contains;
using test::error_message;
using test::TempDir;
using test::write_bytes;

// A cube whose coordinates need all 17 digits, to catch any float rounding.
SurfaceMesh precise_cube() {
  SurfaceMesh m = test::cube();
  m.V = m.V * (1.0 / 3.0) + Eigen::MatrixX3d::Constant(m.V.rows(), 3, M_PI * 1e3);
  return m;
}

TEST(MeshIoTest, TextFormatsRoundTripPolygonsAndDoublePrecision) {
  TempDir dir;
  const SurfaceMesh mesh = precise_cube();
  for (const char* name : {"cube.off", "cube.obj", "cube.ply", "CUBE.OFF", "cube.Ply"}) {
    const std::string path = dir.file(name);
    write_surface_mesh(path, mesh);
    const SurfaceMesh back = read_surface_mesh(path);
    ASSERT_EQ(back.V.rows(), mesh.V.rows()) << name;
    EXPECT_LE((back.V - mesh.V).cwiseAbs().maxCoeff(), 1e-12) << name;
    EXPECT_EQ(back.faces, mesh.faces) << name;  // quads stay quads
  }
}

TEST(MeshIoTest, StlRoundTripTriangulatesAtFloatPrecision) {
  TempDir dir;
  const SurfaceMesh mesh = precise_cube();
  const std::string path = dir.file("cube.stl");
  write_surface_mesh(path, mesh);
  EXPECT_EQ(std::filesystem::file_size(path), 84u + 50u * 12u);
  const SurfaceMesh back = read_surface_mesh(path);
  const Eigen::MatrixX3i triangles = triangulate_faces(mesh);
  ASSERT_EQ(back.V.rows(), mesh.V.rows());  // STL corners merged back into shared vertices
  ASSERT_EQ(back.faces.size(), size_t(triangles.rows()));
  for (size_t t = 0; t < back.faces.size(); ++t) {
    ASSERT_EQ(back.faces[t].size(), 3u);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE((back.V.row(back.faces[t][k]) - mesh.V.row(triangles(t, k))).norm(), 1e-3)
          << "triangle " << t;  // float: ~7 digits of 3141.6
  }
}

TEST(MeshIoTest, NonManifoldFacesAreKeptInEveryFormat) {
  TempDir dir;
  for (const char* name : {"pages.off", "pages.obj", "pages.ply", "pages.stl"}) {
    write_surface_mesh(dir.file(name), test::three_pages());
    const SurfaceMesh back = read_surface_mesh(dir.file(name));
    EXPECT_EQ(back.faces.size(), 3u) << name;
    EXPECT_EQ(check_surface_mesh(back).num_nonmanifold_edges, 1) << name;
  }
}

// Reads `path` expecting an InputError whose one-line message names the file
// and contains `words`.
void expect_read_error(const std::string& path, const std::string& words) {
  const std::string message = error_message<InputError>([&] { read_surface_mesh(path); });
  EXPECT_TRUE(Contains(message, "'" + path + "'"));
  EXPECT_TRUE(Contains(message, words));
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

template <typename T>
void append(std::string* bytes, T value) {
  bytes->append(reinterpret_cast<const char*>(&value), sizeof(value));
}

TEST(MeshIoTest, BinaryPlyOffAndAsciiStlGoThroughOpenMeshKeepingAllFaces) {
  TempDir dir;
  const SurfaceMesh pages = test::three_pages();
  std::string vertices, faces;
  for (Eigen::Index i = 0; i < pages.V.rows(); ++i)
    for (int k = 0; k < 3; ++k) append(&vertices, float(pages.V(i, k)));
  for (const auto& face : pages.faces) {
    append(&faces, uint8_t(face.size()));
    for (int v : face) append(&faces, int32_t(v));
  }
  const std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\n"
      "property float x\nproperty float y\nproperty float z\nelement face 3\n"
      "property list uchar int vertex_indices\nend_header\n" +
      vertices + faces;
  write_bytes(dir.file("pages.ply"), ply);
  SurfaceMesh back = read_surface_mesh(dir.file("pages.ply"));
  EXPECT_EQ(back.V, pages.V);
  EXPECT_EQ(back.faces, pages.faces);
  write_bytes(dir.file("short.ply"), ply.substr(0, ply.size() - 5));
  expect_read_error(dir.file("short.ply"), "cannot parse");

  std::string off = "OFF BINARY\n";
  for (int32_t count : {5, 3, 0}) append(&off, count);
  off += vertices;
  for (const auto& face : pages.faces) {
    append(&off, int32_t(face.size()));
    for (int v : face) append(&off, int32_t(v));
  }
  write_bytes(dir.file("pages.off"), off);
  back = read_surface_mesh(dir.file("pages.off"));
  EXPECT_EQ(back.V, pages.V);
  EXPECT_EQ(back.faces, pages.faces);

  write_bytes(dir.file("tri.stl"),
              "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
              "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
  back = read_surface_mesh(dir.file("tri.stl"));
  EXPECT_EQ(back.V.rows(), 3);
  EXPECT_EQ(back.faces, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(MeshIoTest, ReadsOffVariantsCommentsAndObjIndexForms) {
  TempDir dir;
  write_bytes(dir.file("c.off"),
              "COFF # coloured\n# a comment line\n\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n"
              "0 1 0 255 0 0 255\n0.5 0.5 1 255 0 0 255\n3 0 1 2 10 20 30\n3 0 1 3\n");
  const SurfaceMesh off = read_surface_mesh(dir.file("c.off"));
  EXPECT_EQ(off.V.rows(), 4);
  EXPECT_DOUBLE_EQ(off.V(3, 0), 0.5);
  EXPECT_EQ(off.faces, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 1, 3}}));

  write_bytes(dir.file("i.obj"),
              "# obj\nmtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\r\nvt 0 0\nvn 0 0 1\nv 1 1 0\n"
              "g part\nf 1/1/1 2/1/1 3/1/1\nf -3//1 -1//1 -2//1\n");
  const SurfaceMesh obj = read_surface_mesh(dir.file("i.obj"));
  EXPECT_EQ(obj.V.rows(), 4);
  EXPECT_EQ(obj.faces, (std::vector<std::vector<int>>{{0, 1, 2}, {1, 3, 2}}));
}

TEST(MeshIoTest, NanCoordinatesAreReadAndRejectedByTheCheck) {
  TempDir dir;
  write_bytes(dir.file("nan.off"), "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  const SurfaceMesh mesh = read_surface_mesh(dir.file("nan.off"));
  EXPECT_TRUE(Contains(error_message<InputError>([&] { check_surface_mesh(mesh); }),
                       "vertex 1 has a non-finite coordinate (nan)"));
}

TEST(MeshIoTest, MissingFileAndUnsupportedExtensionsThrow) {
  TempDir dir;
  expect_read_error(dir.file("absent.off"), "No such file");
  write_bytes(dir.file("mesh.xyz"), "OFF\n");
  expect_read_error(dir.file("mesh.xyz"), "unsupported extension '.xyz'");
  write_bytes(dir.file("mesh"), "OFF\n");
  expect_read_error(dir.file("mesh"), "no file extension");
  std::filesystem::create_directory(dir.file("folder.off"));
  expect_read_error(dir.file("folder.off"), "directory");
}

TEST(MeshIoTest, TruncatedFilesThrow) {
  TempDir dir;
  // Long enough that the size pre-check passes and the parser meets the end.
  const std::string off =
      "OFF\n4 4 0\n0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n0.0000 1.0000 0.0000\n"
      "0.0000 0.0000 1.0000\n3 0 1 2\n3 0 3 1\n";
  write_bytes(dir.file("v.off"), off.substr(0, 10 + 3 * 21));
  expect_read_error(dir.file("v.off"), "truncated: 3 of 4 vertices");
  write_bytes(dir.file("f.off"), off);  // OpenMesh would repeat the last face here
  expect_read_error(dir.file("f.off"), "truncated: 2 of 4 faces");
  write_bytes(dir.file("f2.off"), off.substr(0, off.size() - 3));
  expect_read_error(dir.file("f2.off"), "bad vertex list for face 1");

  write_surface_mesh(dir.file("t.ply"), test::tetrahedron());
  std::ifstream in(dir.file("t.ply"));
  const std::string ply((std::istreambuf_iterator<char>(in)), {});
  write_bytes(dir.file("short.ply"), ply.substr(0, ply.size() - 8));
  expect_read_error(dir.file("short.ply"), "truncated: 3 of 4 face elements");

  write_surface_mesh(dir.file("t.stl"), test::tetrahedron());
  std::ifstream stl_in(dir.file("t.stl"), std::ios::binary);
  const std::string stl((std::istreambuf_iterator<char>(stl_in)), {});
  write_bytes(dir.file("short.stl"), stl.substr(0, stl.size() - 20));
  expect_read_error(dir.file("short.stl"), "binary STL");
  write_bytes(dir.file("ascii.stl"), "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n");
  expect_read_error(dir.file("ascii.stl"), "truncated ASCII STL");
}

TEST(MeshIoTest, HugeDeclaredCountsThrowWithoutAllocating) {
  TempDir dir;
  write_bytes(dir.file("huge.off"), "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_read_error(dir.file("huge.off"), "declares 1000000000 vertices and 1000000000 faces");
  write_bytes(dir.file("huge.ply"),
              "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
              "property float x\nproperty float y\nproperty float z\nelement face 1\n"
              "property list uchar int vertex_indices\nend_header\n0000");
  expect_read_error(dir.file("huge.ply"), "declares 1000000000 vertices and 1 faces");
  std::string binary_off = "OFF BINARY\n";
  const int32_t counts[3] = {1000000000, 1000000000, 0};
  binary_off.append(reinterpret_cast<const char*>(counts), sizeof(counts));
  write_bytes(dir.file("huge_binary.off"), binary_off + std::string(100, '\0'));
  expect_read_error(dir.file("huge_binary.off"), "declares 1000000000 vertices");
}

TEST(MeshIoTest, GarbageFilesThrow) {
  TempDir dir;
  std::mt19937 random(7);
  std::string garbage(4000, '\0');
  for (char& c : garbage) c = char(random());
  for (const char* name : {"g.off", "g.obj", "g.ply", "g.stl"}) {
    write_bytes(dir.file(name), garbage);
    expect_read_error(dir.file(name), "");
  }
  write_bytes(dir.file("empty.off"), "");
  expect_read_error(dir.file("empty.off"), "empty");
  write_bytes(dir.file("words.off"), "OFF\nfour two zero\n");
  expect_read_error(dir.file("words.off"), "line 2: bad vertex and face counts");
  write_bytes(dir.file("nofaces.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_read_error(dir.file("nofaces.obj"), "no faces");
}

TEST(MeshIoTest, WriteRejectsUnsupportedExtensionBeforeWriting) {
  TempDir dir;
  const std::string message = error_message<OutputError>(
      [&] { write_surface_mesh(dir.file("mesh.xyz"), test::tetrahedron()); });
  EXPECT_TRUE(Contains(message, "unsupported extension '.xyz'"));
  EXPECT_EQ(dir.count(), 0);
}

TEST(MeshIoTest, AtomicWriteToMissingDirectoryLeavesNothing) {
  TempDir dir;
  const std::string path = dir.file("missing/out.off");
  const std::string message =
      error_message<OutputError>([&] { write_surface_mesh(path, test::tetrahedron()); });
  EXPECT_TRUE(Contains(message, "'" + path + "'"));
  EXPECT_EQ(dir.count(), 0);
}

TEST(MeshIoTest, AtomicWriteKeepsOldFileAndNoTempWhenWriterThrows) {
  TempDir dir;
  const std::string path = dir.file("out.txt");
  write_file_atomically(path, [](std::ostream& out) { out << "old"; });
  const std::string message = error_message<OutputError>([&] {
    write_file_atomically(path, [](std::ostream& out) {
      out << "partial";
      throw std::runtime_error("boom");
    });
  });
  EXPECT_TRUE(Contains(message, "boom"));
  EXPECT_EQ(dir.count(), 1);  // the old file, no temporary
  std::ifstream in(path);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), "old");

  // unfold errors pass through unchanged.
  EXPECT_THROW(write_file_atomically(path, [](std::ostream&) { throw InputError("x"); }),
               InputError);
  EXPECT_EQ(dir.count(), 1);
}

TEST(MeshIoTest, ReadsSharedCentaurWithAllFaces) {
  const std::string path = test::shared_data("tosca/centaur3.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/centaur3.off";
  std::ifstream in(path);
  std::string keyword;
  size_t num_vertices = 0, num_faces = 0;
  in >> keyword >> num_vertices >> num_faces;
  const SurfaceMesh mesh = read_surface_mesh(path);
  EXPECT_EQ(size_t(mesh.V.rows()), num_vertices);
  EXPECT_EQ(mesh.faces.size(), num_faces);
}

}  // namespace
}  // namespace unfold
