#include "energies/soft_joint_factors.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A bar along x (20 x 2 x 2 cells), and the same bar bent in the xy plane as
// a ribbon would bend, isometrically: the cross-section turns with the centre
// line's angle theta(x), gentle everywhere and by a right angle within one cell
// at the middle (the joint).
struct Bar {
  TetMesh mesh = test::grid_tet_mesh(20, 2, 2);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  static double theta(double x) {
    return 0.02 * x + (x <= 10 ? 0 : x >= 11 ? M_PI / 2 : (x - 10) * M_PI / 2);
  }
  Eigen::MatrixX3d bent() const {
    Eigen::MatrixX3d Q(mesh.V.rows(), 3);
    for (Eigen::Index i = 0; i < Q.rows(); ++i) {
      const double x = mesh.V(i, 0), y = mesh.V(i, 1) - 1;
      // The centre line's point at arc length x (midpoint rule, fine steps).
      Eigen::Vector2d c(0, 0);
      const int steps = int(std::round(x * 200));
      for (int s = 0; s < steps; ++s) {
        const double t = (s + 0.5) / 200;
        c += Eigen::Vector2d(std::cos(theta(t)), std::sin(theta(t))) / 200;
      }
      const double a = theta(x);
      Q.row(i) << c.x() - y * std::sin(a), c.y() + y * std::cos(a), mesh.V(i, 2);
    }
    return Q;
  }
};

TEST(SoftJointFactors, SoftenTheJointAndLeaveTheLimbs) {
  const Bar bar;
  const SoftenOptions options{2.0, 0.4};
  const std::vector<double> f = soft_joint_factors(bar.graph, bar.mesh.V, bar.bent(), options);
  ASSERT_EQ(f.size(), size_t(bar.graph.num_edges()));
  double joint = 1, limbs = 0;
  int num_limbs = 0;
  for (int e = 0; e < bar.graph.num_edges(); ++e) {
    EXPECT_GE(f[size_t(e)], options.floor);
    EXPECT_LE(f[size_t(e)], 1.0);
    const double x =
        (bar.mesh.V(bar.graph.edges(e, 0), 0) + bar.mesh.V(bar.graph.edges(e, 1), 0)) / 2;
    if (x > 10 && x < 11) joint = std::min(joint, f[size_t(e)]);
    if (x < 7 || x > 14) limbs += f[size_t(e)], ++num_limbs;
  }
  EXPECT_DOUBLE_EQ(joint, options.floor);  // the right angle within one cell
  EXPECT_GT(limbs / num_limbs, 0.75);      // the gentle bend, about the median turn
}

TEST(SoftJointFactors, IndependentOfScaleAndRigidMotion) {
  const Bar bar;
  const SoftenOptions options{2.0, 0.4};
  const Eigen::MatrixX3d Q = bar.bent();
  const std::vector<double> f = soft_joint_factors(bar.graph, bar.mesh.V, Q, options);
  const Eigen::Matrix3d R = test::random_rotation(7);
  const Eigen::MatrixX3d moved =
      ((3.0 * Q) * R.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  const std::vector<double> g = soft_joint_factors(bar.graph, 3.0 * bar.mesh.V, moved, options);
  for (size_t e = 0; e < f.size(); ++e) EXPECT_NEAR(f[e], g[e], 1e-9) << "edge " << e;
}

TEST(SoftJointFactors, ARigidMotionSoftensNothing) {
  const Bar bar;
  const Eigen::MatrixX3d Q = (bar.mesh.V * test::random_rotation(3).transpose()).rowwise() +
                             Eigen::RowVector3d(0.5, -1, 2);
  for (double f : soft_joint_factors(bar.graph, bar.mesh.V, Q, {2.0, 0.4})) EXPECT_EQ(f, 1.0);
}

TEST(SoftJointFactors, RefusesBadArguments) {
  const Bar bar;
  const Eigen::MatrixX3d Q = bar.bent();
  EXPECT_THROW(soft_joint_factors(bar.graph, bar.mesh.V, Q.topRows(5), {2.0, 0.4}), UsageError);
  EXPECT_THROW(soft_joint_factors(bar.graph, bar.mesh.V, Q, {0.0, 0.4}), UsageError);
  EXPECT_THROW(soft_joint_factors(bar.graph, bar.mesh.V, Q, {2.0, 0.0}), UsageError);
  EXPECT_THROW(soft_joint_factors(bar.graph, bar.mesh.V, Q, {2.0, 1.5}), UsageError);
  EXPECT_THROW(soft_joint_factors(bar.graph, bar.mesh.V, Q, {NAN, 0.4}), UsageError);
}

}  // namespace
}  // namespace unfold
