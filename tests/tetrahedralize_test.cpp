// Tetrahedralization: surface vertices kept first and in order, the volume
// filled, and TetGen's failures turned into errors instead of crashes.
#include "tetra/tetrahedralize.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <set>
#include <vector>

#include "core/errors.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/sort_interior_vertices.h"
#include "test_meshes.h"

namespace unfold {
namespace {

double total_volume(const TetMesh& m) {
  double volume = 0;
  for (Eigen::Index t = 0; t < m.T.rows(); ++t) {
    const Eigen::Vector3d a = m.V.row(m.T(t, 0)), b = m.V.row(m.T(t, 1)), c = m.V.row(m.T(t, 2)),
                          d = m.V.row(m.T(t, 3));
    volume += std::abs((b - a).cross(c - a).dot(d - a)) / 6;
  }
  return volume;
}

TEST(Tetrahedralize, KeepsSurfaceVerticesFirstAndFillsTheVolume) {
  const SurfaceMesh sphere = test::uv_sphere(12, 24, 2.0);
  TetReport report;
  const TetMesh tets = tetrahedralize(sphere, TetOptions{}, &report);
  ASSERT_GE(tets.V.rows(), sphere.V.rows());
  EXPECT_EQ(tets.num_surface_vertices, sphere.V.rows());
  EXPECT_EQ(tets.V.topRows(sphere.V.rows()), sphere.V);
  EXPECT_EQ(report.route, "conforming");
  EXPECT_EQ(report.fallback, "");  // a clean surface: auto tries conforming, which succeeds
  EXPECT_EQ(report.num_tets, tets.T.rows());
  EXPECT_EQ(report.num_interior_points, tets.V.rows() - sphere.V.rows());
  // The inscribed polyhedron's volume: a bit below the sphere's 4/3 pi r^3.
  const double sphere_volume = 4.0 / 3.0 * M_PI * 8.0;
  EXPECT_GT(total_volume(tets), 0.9 * sphere_volume);
  EXPECT_LT(total_volume(tets), sphere_volume);
}

// Sorting the interior vertices renumbers them only: surface rows stay, the
// tets are the same tets (as sets of positions), interior keys ascend.
TEST(Tetrahedralize, InteriorVerticesSortedAlongAZCurveKeepTheMesh) {
  TetOptions options;
  options.max_volume = 0.01;  // interior points
  const TetMesh before = tetrahedralize(test::uv_sphere(10, 20, 1.0), options);
  ASSERT_GT(before.V.rows() - before.num_surface_vertices, 20);
  TetMesh after = before;
  sort_interior_vertices(&after);
  const int first = before.num_surface_vertices;
  EXPECT_EQ(after.V.topRows(first), before.V.topRows(first));
  const auto tet_positions = [](const TetMesh& m) {
    std::multiset<std::vector<double>> tets;
    for (Eigen::Index t = 0; t < m.T.rows(); ++t) {
      std::vector<std::vector<double>> corners;
      for (int c = 0; c < 4; ++c)
        corners.push_back({m.V(m.T(t, c), 0), m.V(m.T(t, c), 1), m.V(m.T(t, c), 2)});
      std::sort(corners.begin(), corners.end());
      std::vector<double> flat;
      for (const auto& corner : corners) flat.insert(flat.end(), corner.begin(), corner.end());
      tets.insert(flat);
    }
    return tets;
  };
  EXPECT_EQ(tet_positions(after), tet_positions(before));
  // Consecutive interior vertices are close: much closer than in TetGen's order.
  const auto mean_step = [first](const TetMesh& m) {
    double sum = 0;
    for (Eigen::Index i = first + 1; i < m.V.rows(); ++i)
      sum += (m.V.row(i) - m.V.row(i - 1)).norm();
    return sum / double(m.V.rows() - first - 1);
  };
  EXPECT_LT(mean_step(after), 0.6 * mean_step(before));
}

TEST(Tetrahedralize, SelfIntersectingSurfaceIsAnErrorNotACrash) {
  const SurfaceMesh folded = test::two_interpenetrating_octahedra();
  TetOptions conforming;
  conforming.route = "conforming";
  try {
    tetrahedralize(folded, conforming);
    FAIL() << "TetGen accepted a self-intersecting surface";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("TetGen"), std::string::npos) << e.what();
  }
}

TEST(Tetrahedralize, UnknownRouteIsAUsageError) {
  TetOptions options;
  options.route = "magic";
  EXPECT_THROW(tetrahedralize(test::octahedron(), options), UsageError);
}

// auto's conforming try runs while the intersecting faces are counted and is
// stopped when they are found: the caller's give_up ends TetGen's process.
TEST(Tetrahedralize, ConformingTryCanBeGivenUp) {
  const SurfaceMesh sphere = test::uv_sphere(12, 24);
  try {
    tetrahedralize_conforming(sphere, 2.0, 0, [] { return true; });
    FAIL() << "not given up before it started";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("given up"), std::string::npos) << e.what();
  }
  // Asked again while TetGen runs (every few milliseconds): the second answer
  // stops it; a sphere this fine takes TetGen far longer than two polls.
  const SurfaceMesh fine = test::uv_sphere(160, 320);
  int asked = 0;
  EXPECT_THROW(tetrahedralize_conforming(fine, 2.0, 0, [&asked] { return ++asked > 2; }),
               NumericalError);
  EXPECT_EQ(asked, 3);
  // Never giving up changes nothing.
  const TetMesh kept = tetrahedralize_conforming(sphere, 2.0, 0, [] { return false; });
  const TetMesh plain = tetrahedralize_conforming(sphere, 2.0);
  EXPECT_EQ(kept.V, plain.V);
  EXPECT_EQ(kept.T, plain.T);
}

}  // namespace
}  // namespace unfold
