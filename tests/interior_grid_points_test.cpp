// The robust route's interior points against every lattice cell tested: the
// lines along x it skips hold none, on closed surfaces and on open and
// misoriented ones, whose winding number is not an integer.
#include "tetra/interior_grid_points.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"

namespace unfold {
namespace {

// Every cell centre of the lattice (the header's definition) with winding
// number (times orientation; fast_winding_number_classify's, which decides
// the side of 1/2 as the tree's accuracy does) above 1/2 and at least
// spacing / 2 from every vertex, in lattice order, sheared.
Eigen::MatrixX3d every_cell_tested(const Eigen::MatrixX3d& V, const FastWindingNumberTree& tree,
                                   double orientation, double spacing) {
  const Eigen::RowVector3d low = V.colwise().minCoeff(), high = V.colwise().maxCoeff();
  const Eigen::Array3i cells = ((high - low) / spacing).array().ceil().cast<int>().max(1);
  Eigen::MatrixX3d Q(cells.prod(), 3), shift(cells.prod(), 3);
  int rows = 0;
  for (int x = 0; x < cells(0); ++x)
    for (int y = 0; y < cells(1); ++y)
      for (int z = 0; z < cells(2); ++z) {
        const Eigen::RowVector3d p = low + spacing * Eigen::RowVector3d(x + 0.5, y + 0.5, z + 0.5);
        if ((V.rowwise() - p).rowwise().norm().minCoeff() < spacing / 2) continue;
        Q.row(rows) = p;
        shift.row(rows++) = kInteriorGridShear * spacing * Eigen::RowVector3d(y + z, x + z, x + y);
      }
  const Eigen::VectorXd w =
      orientation * fast_winding_number_classify(tree, Eigen::MatrixX3d(Q.topRows(rows)));
  Eigen::MatrixX3d inside((w.array() > 0.5).count(), 3);
  for (Eigen::Index k = 0, row = 0; k < rows; ++k)
    if (w(k) > 0.5) inside.row(row++) = Q.row(k) + shift.row(k);
  return inside;
}

void expect_every_inside_cell(const SurfaceMesh& surface, double spacing) {
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  const double orientation = test::signed_volume(surface) < 0 ? -1 : 1;
  const FastWindingNumberTree tree = fast_winding_number_precomputation(surface.V, F);
  const Eigen::MatrixX3d expected = every_cell_tested(surface.V, tree, orientation, spacing);
  const Eigen::MatrixX3d points = interior_grid_points(tree, orientation, spacing);
  ASSERT_GT(expected.rows(), 0);
  ASSERT_EQ(points.rows(), expected.rows());
  EXPECT_EQ((points - expected).cwiseAbs().maxCoeff(), 0.0);
}

// The sphere with its poles turned onto the x axis: lines along x pass
// through both poles.
SurfaceMesh sphere_along_x(int rings, int segments) {
  SurfaceMesh s = test::uv_sphere(rings, segments);
  const Eigen::MatrixX3d V = s.V;
  s.V.col(0) = V.col(2);
  s.V.col(1) = V.col(0);
  s.V.col(2) = V.col(1);
  return s;
}

TEST(InteriorGridPoints, AsEveryCellTestedOnShapesAlongTheBoxsDiagonal) {
  // Two spheres at opposite corners of their box (most lines along x miss
  // both), one of them through the other's twin: closed, self-intersecting.
  SurfaceMesh two = test::uv_sphere(12, 16);
  const int n = int(two.V.rows());
  const SurfaceMesh other = test::uv_sphere(12, 16);
  for (const Eigen::RowVector3d& offset :
       {Eigen::RowVector3d(3, 3, 3), Eigen::RowVector3d(3.8, 3.5, 3.2)}) {
    const int first = int(two.V.rows());
    two.V.conservativeResize(first + n, 3);
    two.V.bottomRows(n) = other.V.rowwise() + offset;
    for (auto f : other.faces) {
      for (int& v : f) v += first;
      two.faces.push_back(f);
    }
  }
  expect_every_inside_cell(two, 0.15);
}

TEST(InteriorGridPoints, AsEveryCellTestedWhereRaysLeaveThroughHoles) {
  // Both polar caps cut away: on the lines along x near the axis no ray meets
  // a triangle, yet the winding number inside is near cos(hole's angle) > 1/2.
  // Only closing the holes (the boundary chain's cones) keeps those lines.
  const SurfaceMesh sphere = sphere_along_x(12, 24);
  SurfaceMesh open = sphere;
  open.faces.clear();
  for (const auto& f : sphere.faces) {
    bool polar = false;
    for (const int v : f) polar = polar || std::abs(sphere.V(v, 0)) > 0.95;
    if (!polar) open.faces.push_back(f);
  }
  expect_every_inside_cell(open, 0.1);
}

TEST(InteriorGridPoints, AsEveryCellTestedWithAPatchTurnedOver) {
  // A band of faces oriented against the rest: a seam chain twice over.
  SurfaceMesh sphere = sphere_along_x(12, 24);
  for (auto& f : sphere.faces) {
    bool band = true;
    for (const int v : f) band = band && sphere.V(v, 1) > 0.3 && sphere.V(v, 2) > 0;
    if (band) std::swap(f[1], f[2]);
  }
  expect_every_inside_cell(sphere, 0.1);
}

}  // namespace
}  // namespace unfold
