#include <gtest/gtest.h>

#include <limits>

#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "tests/test_files.h"
#include "tests/test_meshes.h"

namespace unfold {
namespace {

using test::Contains;
using test::error_message;

std::string check_error(const SurfaceMesh& mesh) {
  return error_message<InputError>([&] { check_surface_mesh(mesh); });
}

TEST(MeshCheckTest, CleanClosedMeshesHaveNoWarnings) {
  for (const SurfaceMesh& mesh :
       {test::tetrahedron(), test::octahedron(), test::cube(), test::uv_sphere(8, 12)}) {
    const SurfaceReport report = check_surface_mesh(mesh);
    EXPECT_EQ(report.num_boundary_edges, 0);
    EXPECT_EQ(report.num_nonmanifold_edges, 0);
    EXPECT_EQ(report.num_misoriented_edges, 0);
    EXPECT_TRUE(report.warnings.empty());
  }
}

TEST(MeshCheckTest, EmptyMeshThrows) {
  EXPECT_TRUE(Contains(check_error(SurfaceMesh{}), "empty (0 vertices, 0 faces)"));
  SurfaceMesh no_faces = test::tetrahedron();
  no_faces.faces.clear();
  EXPECT_TRUE(Contains(check_error(no_faces), "empty (4 vertices, 0 faces)"));
}

TEST(MeshCheckTest, SizesFrom1eMinus30To1e30PassAndBeyondAreNamed) {
  // The octahedron's bounding-box diagonal is 2 sqrt(3).
  const SurfaceMesh unit = test::octahedron();
  for (double scale : {1.1e-30 / 3.4641, 0.9e30 / 3.4641}) {
    SurfaceMesh scaled = unit;
    scaled.V *= scale;
    EXPECT_NO_THROW(check_surface_mesh(scaled)) << scale;
  }
  SurfaceMesh huge = unit, tiny = unit, overflowing = unit;
  huge.V *= 1e31;
  tiny.V *= 1e-31;
  overflowing.V *= 1e308;  // max - min overflows to inf
  EXPECT_TRUE(Contains(check_error(huge), "coordinates too large to process"));
  EXPECT_TRUE(Contains(check_error(tiny), "coordinates too small to process"));
  EXPECT_TRUE(Contains(check_error(overflowing), "diagonal is more than 1.8e308"));
}

TEST(MeshCheckTest, NonFiniteCoordinateNamesVertex) {
  SurfaceMesh mesh = test::octahedron();
  mesh.V(4, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_error(mesh), "vertex 4 has a non-finite coordinate (nan)");
  mesh.V(4, 1) = 0;
  mesh.V(2, 2) = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(check_error(mesh), "vertex 2 has a non-finite coordinate (-inf)");
}

TEST(MeshCheckTest, ShortFaceNamesFace) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.faces[2] = {0, 2};
  EXPECT_TRUE(Contains(check_error(mesh), "face 2 has 2 vertices"));
}

TEST(MeshCheckTest, IndexOutOfRangeNamesFaceAndVertex) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.faces[3][1] = 9999;
  EXPECT_EQ(check_error(mesh), "face 3 refers to vertex 9999 but the mesh has 4 vertices");
  mesh.faces[3][1] = -1;
  EXPECT_TRUE(Contains(check_error(mesh), "face 3 refers to vertex -1"));
}

TEST(MeshCheckTest, RepeatedVertexNamesFace) {
  SurfaceMesh mesh = test::cube();
  mesh.faces[1] = {4, 5, 4, 7};
  EXPECT_EQ(check_error(mesh), "face 1 repeats vertex 4");
}

TEST(MeshCheckTest, ZeroAreaFaceNamesFace) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.V.row(3) = 0.5 * (mesh.V.row(0) + mesh.V.row(1));  // face 1 (0 3 1) becomes a segment
  EXPECT_TRUE(Contains(check_error(mesh), "face 1 has zero area"));
}

TEST(MeshCheckTest, UnusedVertexNamesVertex) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.V.conservativeResize(5, 3);
  mesh.V.row(4) << 3, 3, 3;
  EXPECT_EQ(check_error(mesh), "vertex 4 is used by no face");
}

TEST(MeshCheckTest, SeveralComponentsListsSizes) {
  SurfaceMesh mesh = test::octahedron();
  for (int copy = 0; copy < 2; ++copy) {
    const SurfaceMesh tet = test::tetrahedron();
    const int offset = int(mesh.V.rows());
    mesh.V.conservativeResize(offset + 4, 3);
    mesh.V.bottomRows(4) = tet.V.rowwise() + Eigen::RowVector3d(5.0 * (copy + 1), 0, 0);
    for (auto face : tet.faces) {
      for (int& v : face) v += offset;
      mesh.faces.push_back(face);
    }
  }
  EXPECT_EQ(check_error(mesh),
            "the surface has 3 connected components (sizes 6, 4, 4); unfold needs one (or "
            "components: separately)");
}

TEST(MeshCheckTest, FatalChecksRunInDocumentedOrder) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.faces[0] = {0, 99, 1};  // out of range ...
  mesh.faces[3] = {1, 3};      // ... but the short face is reported first
  EXPECT_TRUE(Contains(check_error(mesh), "face 3 has 2 vertices"));
  mesh.V(1, 0) = std::numeric_limits<double>::infinity();  // ... and a bad vertex before that
  EXPECT_TRUE(Contains(check_error(mesh), "vertex 1 has a non-finite coordinate (inf)"));
}

TEST(MeshCheckTest, OpenSurfaceReportsBoundaryEdges) {
  SurfaceMesh mesh = test::tetrahedron();
  mesh.faces.pop_back();  // drops face 1 3 2
  const SurfaceReport report = check_surface_mesh(mesh);
  EXPECT_EQ(report.num_boundary_edges, 3);
  EXPECT_EQ(report.num_nonmanifold_edges, 0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(Contains(report.warnings[0], "open surface: 3 boundary edges (e.g. edge 1-2)"));
}

TEST(MeshCheckTest, ThreeFacesOnOneEdgeReportOneNonManifoldEdge) {
  const SurfaceReport report = check_surface_mesh(test::three_pages());
  EXPECT_EQ(report.num_nonmanifold_edges, 1);
  EXPECT_EQ(report.num_boundary_edges, 6);
  bool named = false;
  for (const auto& w : report.warnings)
    named = named || Contains(w,
                              "1 non-manifold edges shared by more than two faces (e.g. "
                              "edge 0-1, in 3 faces)");
  EXPECT_TRUE(named);
}

TEST(MeshCheckTest, FlippedFaceReportsMisorientedEdges) {
  SurfaceMesh mesh = test::octahedron();
  std::swap(mesh.faces[5][0], mesh.faces[5][1]);
  const SurfaceReport report = check_surface_mesh(mesh);
  EXPECT_EQ(report.num_misoriented_edges, 3);
  EXPECT_EQ(report.num_boundary_edges, 0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(Contains(report.warnings[0], "inconsistent face orientation across 3 edges"));
}

TEST(MeshCheckTest, TwoClosedSurfacesTouchingAtAVertexReportANonManifoldVertex) {
  SurfaceMesh mesh = test::tetrahedron();  // a second tetrahedron shares vertex 0 only
  mesh.V.conservativeResize(7, 3);
  mesh.V.bottomRows(3) << 3, 1, 1, 1, 3, 1, 1, 1, 3;
  for (const std::vector<int>& f : {std::vector<int>{0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}})
    mesh.faces.push_back(f);
  const SurfaceReport report = check_surface_mesh(mesh);
  EXPECT_EQ(report.num_nonmanifold_vertices, 1);
  EXPECT_EQ(report.num_nonmanifold_edges, 0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(Contains(report.warnings[0], "1 non-manifold vertices"));
  EXPECT_TRUE(Contains(report.warnings[0], "vertex 0"));
  EXPECT_EQ(check_surface_mesh(test::octahedron()).num_nonmanifold_vertices, 0);
  EXPECT_EQ(check_surface_mesh(test::three_pages()).num_nonmanifold_vertices, 0);
}

TEST(MeshCheckTest, ComponentsCountedWhenOneIsNotRequired) {
  SurfaceMesh mesh = test::tetrahedron();
  const SurfaceMesh other = test::octahedron();
  mesh.V.conservativeResize(10, 3);
  mesh.V.bottomRows(6) = other.V.array() + 5.0;
  for (auto f : other.faces) {
    for (int& v : f) v += 4;
    mesh.faces.push_back(f);
  }
  EXPECT_EQ(check_surface_mesh(mesh, false).num_components, 2);
  EXPECT_TRUE(Contains(check_error(mesh), "2 connected components (sizes 6, 4)"));
}

}  // namespace
}  // namespace unfold
