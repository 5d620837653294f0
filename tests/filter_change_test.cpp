#include "solvers/filter_change.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A bar along x, 40 x 2 x 2 cells of size 1, and the same bar hinged by a
// right angle about the z axis at x = 20 (the far half turned as one piece).
struct HingedBar {
  TetMesh mesh = test::grid_tet_mesh(40, 2, 2);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  Eigen::MatrixX3d hinged() const {
    Eigen::MatrixX3d Q = mesh.V;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).matrix();
    const Eigen::RowVector3d hinge(20, 1, 0);
    for (Eigen::Index i = 0; i < Q.rows(); ++i)
      if (mesh.V(i, 0) > 20) Q.row(i) = (mesh.V.row(i) - hinge) * R.transpose() + hinge;
    return Q;
  }
  // Mean position of the vertices with x in [from, to] at rest.
  Eigen::RowVector3d centroid(const Eigen::MatrixX3d& Q, double from, double to) const {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    int count = 0;
    for (Eigen::Index i = 0; i < Q.rows(); ++i)
      if (mesh.V(i, 0) >= from && mesh.V(i, 0) <= to) sum += Q.row(i), ++count;
    return sum / count;
  }
  Eigen::RowVector3d far_direction(const Eigen::MatrixX3d& Q) const {
    return (centroid(Q, 34, 40) - centroid(Q, 26, 32)).normalized();
  }
};

double rms(const Eigen::MatrixXd& m) { return std::sqrt(m.squaredNorm() / double(m.rows())); }

TEST(FilterChange, ARigidMotionComesBackUnchanged) {
  const HingedBar bar;
  const Eigen::MatrixX3d S1 = bar.hinged();
  const Eigen::MatrixX3d S2 =
      (S1 * test::random_rotation(4).transpose()).rowwise() + Eigen::RowVector3d(3, -1, 2);
  const Eigen::MatrixX3d S = filter_change(bar.graph, bar.mesh.V, S1, S2, {2.0, 6.0});
  EXPECT_LT((S - S2).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(FilterChange, NoLengthKeepsTheSecondSolution) {
  const HingedBar bar;
  const Eigen::MatrixX3d S2 = bar.hinged() + 0.1 * Eigen::MatrixX3d::Random(bar.mesh.V.rows(), 3);
  EXPECT_EQ(filter_change(bar.graph, bar.mesh.V, bar.mesh.V, S2, {}), S2);
}

// The change from the straight bar: the hinge's right angle, and wrinkles one
// cell long (z alternating by 0.15 along x). Filtered at 2 and 6 cells, the far
// half keeps its turn and the wrinkles are mostly gone; the mean stays.
TEST(FilterChange, AJointsTurnPassesAndFineWrinklesDoNot) {
  const HingedBar bar;
  const Eigen::MatrixX3d hinged = bar.hinged();
  Eigen::MatrixX3d wrinkled = hinged;
  for (Eigen::Index i = 0; i < wrinkled.rows(); ++i)
    wrinkled(i, 2) += 0.15 * (int(std::lround(bar.mesh.V(i, 0))) % 2 == 0 ? 1 : -1);
  const Eigen::MatrixX3d S = filter_change(bar.graph, bar.mesh.V, bar.mesh.V, wrinkled, {2.0, 6.0});
  const double turn =
      std::acos(std::clamp(double(bar.far_direction(S).dot(bar.far_direction(hinged))), -1.0, 1.0));
  EXPECT_LT(turn, 3 * M_PI / 180) << turn;
  // The bend is in the xy plane: z holds the wrinkles alone.
  EXPECT_LT(rms(S.col(2) - hinged.col(2)), 0.25 * rms(wrinkled.col(2) - hinged.col(2)))
      << rms(S.col(2) - hinged.col(2));
  EXPECT_LT((S.colwise().mean() - wrinkled.colwise().mean()).norm(), 1e-6);
}

TEST(FilterChange, RefusesBadInput) {
  const HingedBar bar;
  const Eigen::MatrixX3d& P = bar.mesh.V;
  EXPECT_THROW(filter_change(bar.graph, P, P.topRows(5), P, {1.0, 1.0}), UsageError);
  EXPECT_THROW(filter_change(bar.graph, P, P, P, {-1.0, 1.0}), UsageError);
  EXPECT_THROW(filter_change(bar.graph, P, P, P, {1.0, NAN}), UsageError);
}

}  // namespace
}  // namespace unfold
