#include <gtest/gtest.h>

#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/simplify_surface_mesh.h"
#include "tests/test_meshes.h"

namespace unfold {
namespace {

TEST(MeshSimplifyTest, SphereKeepsClosedSingleComponentAtTarget) {
  const SurfaceMesh sphere = test::uv_sphere(50, 50);
  ASSERT_EQ(sphere.V.rows(), 2452);
  const SurfaceMesh simple = simplify_surface_mesh(sphere, 500);
  EXPECT_NEAR(double(simple.V.rows()), 500.0, 25.0);
  // check_surface_mesh throws on unused vertices, degenerate faces or several components.
  const SurfaceReport report = check_surface_mesh(simple);
  EXPECT_EQ(report.num_boundary_edges, 0);
  EXPECT_EQ(report.num_nonmanifold_edges, 0);
  EXPECT_EQ(report.num_misoriented_edges, 0);
  EXPECT_EQ(simple.faces.size(), size_t(2 * simple.V.rows() - 4));  // closed genus 0
  for (Eigen::Index i = 0; i < simple.V.rows(); ++i)
    EXPECT_NEAR(simple.V.row(i).norm(), 1.0, 0.05) << "vertex " << i << " left the sphere";
}

TEST(MeshSimplifyTest, TargetAtOrAboveSizeReturnsInput) {
  const SurfaceMesh cube = test::cube();
  const SurfaceMesh same = simplify_surface_mesh(cube, 8);
  EXPECT_EQ(same.faces, cube.faces);  // quads untouched
  EXPECT_EQ(same.V, cube.V);
}

TEST(MeshSimplifyTest, TooSmallTargetIsUsageError) {
  EXPECT_THROW(simplify_surface_mesh(test::octahedron(), 3), UsageError);
}

TEST(MeshSimplifyTest, BadIndexIsInputError) {
  SurfaceMesh mesh = test::uv_sphere(6, 6);
  mesh.faces[3][2] = 1000;
  EXPECT_THROW(simplify_surface_mesh(mesh, 10), InputError);
}

TEST(MeshSimplifyTest, NonManifoldFacesAreLeftOutNotFatal) {
  SurfaceMesh mesh = test::uv_sphere(10, 10);
  const int n = int(mesh.V.rows());
  mesh.V.conservativeResize(n + 1, 3);
  mesh.V.row(n) << 2, 0, 0;
  mesh.faces.push_back({mesh.faces[0][0], mesh.faces[0][1], n});  // third face on an edge
  const SurfaceMesh simple = simplify_surface_mesh(mesh, 40);
  EXPECT_NEAR(double(simple.V.rows()), 40.0, 2.0);
  // The extra face and its now isolated vertex are gone; the sphere is intact.
  EXPECT_EQ(check_surface_mesh(simple).num_boundary_edges, 0);
}

}  // namespace
}  // namespace unfold
