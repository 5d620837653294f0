// A tet mesh given instead of made: the boundary extracted or checked, every
// reader, and the round trip --rest_tet_output -> --tet_input, which must
// unfold to the same canonical form.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/errors.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/read_tet_mesh.h"
#include "mesh/tet_mesh_boundary.h"
#include "mesh/tet_volumes.h"
#include "mesh/write_surface_mesh.h"
#include "pipeline/prepare_mesh_from_tets.h"
#include "run_app.h"
#include "shapes/articulated_shape.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

using test::run_unfold;

double max_difference(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  return a.rows() == b.rows() ? (a - b).cwiseAbs().maxCoeff() : 1e300;
}

TEST(TetInput, BoundaryOfAGridIsItsClosedOutwardSurface) {
  const TetMesh grid = test::grid_tet_mesh(2, 2, 2);  // 27 vertices, 26 on the boundary
  const SurfaceMesh boundary = tet_mesh_boundary(grid.V, grid.T);
  EXPECT_EQ(boundary.V.rows(), 26);
  EXPECT_EQ(boundary.faces.size(), 6u * 4 * 2);  // 6 sides of 2 x 2 squares, 2 triangles each
  // Outward: the enclosed volume is positive and equals the box's (2^3).
  const Eigen::MatrixX3i F = triangulate_faces(boundary);
  double volume = 0;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    volume += boundary.V.row(F(t, 0)).dot(boundary.V.row(F(t, 1)).cross(boundary.V.row(F(t, 2))));
  EXPECT_NEAR(volume / 6, 8.0, 1e-12);
  // Boundary vertices keep their order: the middle vertex (13) is the one left out.
  EXPECT_EQ(boundary.V.row(12), grid.V.row(12));
  EXPECT_EQ(boundary.V.row(13), grid.V.row(14));
}

TEST(TetInput, PrepareOrdersTheSurfaceFirstAndRefusesAnotherSurface) {
  const TetMesh grid = test::grid_tet_mesh(2, 2, 2);
  SurfaceMesh surface = tet_mesh_boundary(grid.V, grid.T);
  // The surface's vertices in another order: they come first, in that order.
  surface.V.row(0).swap(surface.V.row(5));
  for (auto& face : surface.faces)
    for (int& v : face) v = v == 0 ? 5 : v == 5 ? 0 : v;
  const Options options;
  const PreparedMesh prepared = prepare_mesh_from_tets(surface, grid.V, grid.T, options);
  EXPECT_EQ(prepared.tets.num_surface_vertices, 26);
  EXPECT_EQ(prepared.tets.V.topRows(26), surface.V);
  EXPECT_EQ(prepared.tets.V.row(26), grid.V.row(13));
  EXPECT_EQ(prepared.tet_report.route, "given");
  // Same tets, renumbered: the same volumes in the same order.
  EXPECT_LT((tet_volumes(prepared.tets.V, prepared.tets.T) - tet_volumes(grid.V, grid.T))
                .cwiseAbs()
                .maxCoeff(),
            1e-15);

  SurfaceMesh moved = surface;
  moved.V(3, 0) += 0.5;
  EXPECT_TRUE(test::Contains(test::error_message<InputError>(
                                 [&] { prepare_mesh_from_tets(moved, grid.V, grid.T, options); }),
                             "surface vertex 3 is not a vertex of the tet mesh"));
  // The surface's vertices without all its triangles on the boundary (as in a
  // carved tet mesh): a warning that counts them.
  SurfaceMesh fewer = surface;
  fewer.faces.pop_back();
  const PreparedMesh carved = prepare_mesh_from_tets(fewer, grid.V, grid.T, options);
  ASSERT_FALSE(carved.warnings.empty());
  EXPECT_TRUE(test::Contains(carved.warnings.back(),
                             "0 of the surface's 47 triangles are not boundary triangles of the "
                             "tet mesh, and 1 of its 48 boundary triangles are not surface"));
}

TEST(TetInput, ReadersRefuseBadFiles) {
  test::TempDir dir;
  test::write_bytes(dir.file("a.vtu"), "<VTKFile type=\"UnstructuredGrid\"><Points>");
  EXPECT_THROW(read_tet_mesh(dir.file("a.vtu")), InputError);
  test::write_bytes(dir.file("b.mesh"), "MeshVersionFormatted 1\nDimension 3\nVertices 1000000\n");
  EXPECT_THROW(read_tet_mesh(dir.file("b.mesh")), InputError);
  test::write_bytes(dir.file("c.msh"), "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
  EXPECT_TRUE(test::Contains(
      test::error_message<InputError>([&] { read_tet_mesh(dir.file("c.msh")); }), "binary"));
  test::write_bytes(dir.file("d.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  test::write_bytes(dir.file("d.ele"), "1 4 0\n0 0 1 2 9\n");
  EXPECT_TRUE(test::Contains(
      test::error_message<InputError>([&] { read_tet_mesh(dir.file("d.node")); }), "vertex 9"));
  EXPECT_THROW(read_tet_mesh(dir.file("e.obj")), InputError);
}

// The input's tets (shape input) given back unfold exactly as they did.
TEST(TetInput, RestTetOutputGivenBackUnfoldsToTheSameCanonicalForm) {
  test::TempDir dir;
  const std::string shape = dir.file("shape.off");
  write_surface_mesh(shape, make_articulated_shape(ShapePose::preset(0), 20));
  ASSERT_EQ(run_unfold("--tet_shape input --input " + shape + " --output " + dir.file("first.off") +
                       " --rest_tet_output " + dir.file("rest.vtu"))
                .exit_code,
            0);
  ASSERT_EQ(run_unfold("--tet_shape input --input " + shape + " --rest_tet_output " +
                       dir.file("rest.node") + " --output " + dir.file("first_again.off"))
                .exit_code,
            0);
  const SurfaceMesh first = read_surface_mesh(dir.file("first.off"));
  const TetMeshData rest = read_tet_mesh(dir.file("rest.vtu"));
  EXPECT_EQ(rest.V.topRows(first.V.rows()), read_surface_mesh(shape).V);
  for (const std::string tets : {"rest.vtu", "rest.node"}) {
    // The boundary taken from the tet mesh, and the surface given beside it.
    const test::AppRun alone = run_unfold("-v --tet_shape input --tet_input " + dir.file(tets) +
                                          " --output " + dir.file("alone.off"));
    ASSERT_EQ(alone.exit_code, 0) << alone.err;
    EXPECT_NE(alone.err.find("given tet mesh"), std::string::npos) << alone.err;
    EXPECT_LT(max_difference(read_surface_mesh(dir.file("alone.off")).V, first.V), 1e-9) << tets;
    const test::AppRun with_surface =
        run_unfold("--tet_shape input --input " + shape + " --tet_input " + dir.file(tets) +
                   " --output " + dir.file("with.off"));
    ASSERT_EQ(with_surface.exit_code, 0) << with_surface.err;
    const SurfaceMesh with = read_surface_mesh(dir.file("with.off"));
    EXPECT_EQ(with.faces, first.faces);
    EXPECT_LT(max_difference(with.V, first.V), 1e-9) << tets;
  }
  // A surface that is not the tet mesh's boundary: a one-line input error, no output.
  const std::string other = dir.file("other.off");
  write_surface_mesh(other, make_articulated_shape(ShapePose::preset(1), 20));
  test::expect_failure("--input " + other + " --tet_input " + dir.file("rest.vtu"), 3,
                       "is not the surface", dir.file("never.off"));
}

// The default's rest tets (the unfolded shape's, carved by the robust route)
// hold the surface's vertices, not all its triangles on their boundary. Given
// back as the .vtu the run wrote (with where they were made, "unfolded"), they
// unfold to the same canonical form; as a .node (no such array) they unfold as
// the input's tets, with a warning on the boundary; shape unfolded would make
// tets of its own instead, and is refused.
TEST(TetInput, DefaultRestTetsGivenBackUnfoldToTheSameCanonicalForm) {
  test::TempDir dir;
  const std::string shape = dir.file("shape.off");
  // At the demo's resolution: coarser, the interior's start no longer shows.
  write_surface_mesh(shape, make_articulated_shape(ShapePose::preset(0)));
  ASSERT_EQ(run_unfold("--input " + shape + " --output " + dir.file("first.off") +
                       " --rest_tet_output " + dir.file("rest.vtu"))
                .exit_code,
            0);
  ASSERT_EQ(
      run_unfold("--input " + shape + " --rest_tet_output " + dir.file("rest.node")).exit_code, 0);
  const SurfaceMesh first = read_surface_mesh(dir.file("first.off"));
  const TetMeshData rest = read_tet_mesh(dir.file("rest.vtu"));
  ASSERT_EQ(rest.unfolded.rows(), rest.V.rows());
  EXPECT_GT((rest.unfolded - rest.V).norm(), 0);  // made elsewhere than at rest
  const test::AppRun given =
      run_unfold("--input " + shape + " --tet_input " + dir.file("rest.vtu") + " --output " +
                 dir.file("given.off"));
  ASSERT_EQ(given.exit_code, 0) << given.err;
  EXPECT_NE(given.err.find("boundary is not exactly the surface"), std::string::npos) << given.err;
  const SurfaceMesh canonical = read_surface_mesh(dir.file("given.off"));
  EXPECT_EQ(canonical.faces, first.faces);
  const double size = (first.V.colwise().maxCoeff() - first.V.colwise().minCoeff()).norm();
  EXPECT_LT(max_difference(canonical.V, first.V), 1e-9 * size);

  const test::AppRun node = run_unfold("--input " + shape + " --tet_input " +
                                       dir.file("rest.node") + " --output " + dir.file("node.off"));
  ASSERT_EQ(node.exit_code, 0) << node.err;
  const SurfaceMesh from_node = read_surface_mesh(dir.file("node.off"));
  EXPECT_TRUE(from_node.V.allFinite());
  EXPECT_GT(max_difference(from_node.V, first.V), 1e-6 * size);  // another route: the test sees it
  test::expect_failure("--tet_shape unfolded --input " + shape + " --tet_input " +
                           dir.file("rest.vtu") + " --output " + dir.file("never.off"),
                       2, "tetrahedralize.shape: unfolded", dir.file("never.off"));
}

}  // namespace
}  // namespace unfold
