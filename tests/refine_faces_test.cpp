// refine_faces: red-green 1-to-4 refinement keeps the surface, its
// orientation, its closedness and the input's vertices, on hand-made meshes
// whose counts are known.
#include "mesh/refine_faces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <set>
#include <utility>

#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "metrics/pose_invariance.h"
#include "tests/test_meshes.h"

namespace unfold {
namespace {

int euler_characteristic(const SurfaceMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const auto& f : mesh.faces)
    for (size_t k = 0; k < f.size(); ++k) edges.insert(std::minmax(f[k], f[(k + 1) % f.size()]));
  return int(mesh.V.rows()) - int(edges.size()) + int(mesh.faces.size());
}

// What every refinement of a closed, outward-oriented mesh must keep.
void expect_same_closed_surface(const SurfaceMesh& in, const SurfaceMesh& out) {
  const SurfaceReport report = check_surface_mesh(out);
  EXPECT_EQ(report.num_boundary_edges, 0);  // a T-junction would leave boundary edges
  EXPECT_EQ(report.num_nonmanifold_edges, 0);
  EXPECT_EQ(report.num_misoriented_edges, 0);
  EXPECT_NEAR(surface_area(out), surface_area(in), 1e-12 * surface_area(in));
  EXPECT_NEAR(test::signed_volume(out), test::signed_volume(in),
              1e-12 * std::abs(test::signed_volume(in)));
  EXPECT_GT(test::signed_volume(out), 0);
  EXPECT_EQ(euler_characteristic(out), euler_characteristic(in));
  ASSERT_GE(out.V.rows(), in.V.rows());
  EXPECT_EQ(out.V.topRows(in.V.rows()), in.V);
}

TEST(RefineFaces, OneTetrahedronFaceSplitsInFourItsNeighboursInTwo) {
  const SurfaceMesh tet = test::tetrahedron();
  const SurfaceMesh out = refine_faces(tet, {0});
  expect_same_closed_surface(tet, out);
  EXPECT_EQ(out.V.rows(), 4 + 3);
  EXPECT_EQ(out.faces.size(), 4u + 3u * 2u);
  // Face 0's children come first, with the midpoints of its edges.
  EXPECT_EQ(out.faces[0], (std::vector<int>{0, 4, 6}));
  EXPECT_EQ(out.faces[3], (std::vector<int>{4, 5, 6}));
  EXPECT_EQ(out.V.row(4), 0.5 * (tet.V.row(0) + tet.V.row(1)));
}

TEST(RefineFaces, OneOctahedronFaceAndAFaceWithTwoSplitEdgesIsMadeRed) {
  const SurfaceMesh oct = test::octahedron();
  const SurfaceMesh one = refine_faces(oct, {3});
  expect_same_closed_surface(oct, one);
  EXPECT_EQ(one.V.rows(), 6 + 3);
  EXPECT_EQ(one.faces.size(), 4u + 3u * 2u + 4u);
  // Faces 0 and 2 meet only at the top vertex: faces 1 and 3 get two split
  // edges each and are refined too; the four lower faces are halved.
  const SurfaceMesh two = refine_faces(oct, {2, 0, 0});
  expect_same_closed_surface(oct, two);
  EXPECT_EQ(two.V.rows(), 6 + 8);
  EXPECT_EQ(two.faces.size(), 4u * 4u + 4u * 2u);
  const SurfaceMesh all = refine_faces(oct, {0, 1, 2, 3, 4, 5, 6, 7});
  expect_same_closed_surface(oct, all);
  EXPECT_EQ(all.V.rows(), 6 + 12);
  EXPECT_EQ(all.faces.size(), 32u);
  EXPECT_EQ(refine_faces(oct, {}).faces, oct.faces);
}

TEST(RefineFaces, RepeatedRefinementOfHalfASphereStaysClosed) {
  const SurfaceMesh sphere = test::uv_sphere(10, 16);
  SurfaceMesh mesh = sphere;
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<int> upper;
    for (size_t f = 0; f < mesh.faces.size(); ++f)
      if (mesh.V(mesh.faces[f][0], 2) + mesh.V(mesh.faces[f][1], 2) + mesh.V(mesh.faces[f][2], 2) >
          0)
        upper.push_back(int(f));
    const SurfaceMesh finer = refine_faces(mesh, upper);
    expect_same_closed_surface(mesh, finer);
    EXPECT_GE(finer.faces.size(), mesh.faces.size() + 3 * upper.size());
    mesh = finer;
  }
  EXPECT_EQ(mesh.V.topRows(sphere.V.rows()), sphere.V);
}

TEST(RefineFaces, RefusesPolygonsAndFacesOutOfRange) {
  EXPECT_THROW(refine_faces(test::cube(), {0}), UsageError);
  EXPECT_THROW(refine_faces(test::tetrahedron(), {4}), UsageError);
  EXPECT_THROW(refine_faces(test::tetrahedron(), {-1}), UsageError);
  SurfaceMesh bad = test::tetrahedron();
  bad.faces[1][2] = 9;
  EXPECT_THROW(refine_faces(bad, {0}), UsageError);
}

}  // namespace
}  // namespace unfold
