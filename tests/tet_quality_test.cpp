// Tet quality: 1 for a regular tet, 0 for a flat one, blind to rigid
// motions, scale and corner order.
#include "mesh/tet_quality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"

namespace unfold {
namespace {

Eigen::MatrixX3d regular_tet() {
  Eigen::MatrixX3d V(4, 3);
  V << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  return V;
}

TEST(TetQuality, IsOneForARegularTetWhateverItsPlaceSizeAndOrder) {
  const Eigen::MatrixX3d V = regular_tet();
  Eigen::MatrixX4i T(2, 4);
  T << 0, 1, 2, 3, 1, 0, 2, 3;  // both orientations
  const Eigen::MatrixX3d moved =
      (3.7 * V * test::random_rotation(2).transpose()).rowwise() + Eigen::RowVector3d(5, -1, 2);
  for (const Eigen::MatrixX3d* P : {&V, &moved}) {
    const Eigen::VectorXd q = tet_quality(*P, T);
    EXPECT_NEAR(q[0], 1.0, 1e-12);
    EXPECT_NEAR(q[1], 1.0, 1e-12);
  }
}

// A tet whose apex comes down onto its base: the quality falls to zero with
// its height, and is zero where corners coincide.
TEST(TetQuality, FallsToZeroAsATetFlattens) {
  Eigen::MatrixX4i T(1, 4);
  T << 0, 1, 2, 3;
  double last = 2;
  for (const double h : {1.0, 0.3, 0.1, 0.01, 0.0}) {
    Eigen::MatrixX3d V(4, 3);
    V << 0, 0, 0, 1, 0, 0, 0.5, 0.9, 0, 0.5, 0.3, h;
    const double q = tet_quality(V, T)[0];
    EXPECT_LT(q, last) << "height " << h;
    EXPECT_GE(q, 0.0);
    last = q;
  }
  EXPECT_EQ(last, 0.0);
  EXPECT_EQ(tet_quality(Eigen::MatrixX3d::Zero(4, 3), T)[0], 0.0);
  // A third of the flattest's height, a third of its quality.
  Eigen::MatrixX3d V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0.5, 0.9, 0, 0.5, 0.3, 0.003;
  const double q3 = tet_quality(V, T)[0];
  V(3, 2) = 0.001;
  EXPECT_NEAR(tet_quality(V, T)[0], q3 / 3, 1e-3 * q3);
}

}  // namespace
}  // namespace unfold
