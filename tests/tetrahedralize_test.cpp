// Tetrahedralization: surface vertices kept first and in order, the volume
// filled, and TetGen's failures turned into errors instead of crashes.
#include "tetra/tetrahedralize.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/errors.h"
#include "mesh/read_surface_mesh.h"
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
  EXPECT_EQ(report.num_tets, tets.T.rows());
  EXPECT_EQ(report.num_interior_points, tets.V.rows() - sphere.V.rows());
  // The inscribed polyhedron's volume: a bit below the sphere's 4/3 pi r^3.
  const double sphere_volume = 4.0 / 3.0 * M_PI * 8.0;
  EXPECT_GT(total_volume(tets), 0.9 * sphere_volume);
  EXPECT_LT(total_volume(tets), sphere_volume);
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

}  // namespace
}  // namespace unfold
