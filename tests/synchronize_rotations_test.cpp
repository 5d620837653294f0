// Rotation synchronization (solvers/synchronize_rotations.h): the rotations of
// a collection recovered from noisy relative ones, a minority of them turned
// round (as a body placed back to front), each component on its own; a tree
// keeps its measurements.
#include "solvers/synchronize_rotations.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "core/errors.h"
#include "test_meshes.h"

namespace unfold {
namespace {

double angle_degrees(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  return Eigen::AngleAxisd(A.transpose() * B).angle() * 180 / M_PI;
}

// A small rotation of about `degrees` about a random axis.
Eigen::Matrix3d jitter(std::mt19937& random, double degrees) {
  std::normal_distribution<double> normal(0, 1);
  const Eigen::Vector3d axis(normal(random), normal(random), normal(random));
  return Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()).toRotationMatrix();
}

// x_to = R x_from when member a's frame is G_a^T of a common one: R = G_to^T G_from.
Eigen::Matrix3d relative(const std::vector<Eigen::Matrix3d>& G, int from, int to) {
  return G[to].transpose() * G[from];
}

TEST(SynchronizeRotations, CorrectsATurnedRoundMinority) {
  std::mt19937 random(11);
  const int n = 9;
  std::vector<Eigen::Matrix3d> G;
  for (int a = 0; a < n; ++a) G.push_back(test::random_rotation(100 + a));
  std::vector<RelativeRotation> measured;
  std::vector<char> corrupted;
  // Every pair, 2 degrees of noise; member 2's pairs with 3, 4 and 6 and
  // member 8's with 1 turned round about a random axis.
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const bool bad = (a == 2 && (b == 3 || b == 4 || b == 6)) || (a == 1 && b == 8);
      Eigen::Matrix3d R = relative(G, a, b) * jitter(random, 2);
      if (bad) R = R * jitter(random, 180);
      measured.push_back({a, b, R});
      corrupted.push_back(bad);
    }
  const SynchronizedRotations sync = synchronize_rotations(n, measured);
  ASSERT_EQ(sync.implied.size(), measured.size());
  for (size_t e = 0; e < measured.size(); ++e) {
    const RelativeRotation& m = measured[e];
    EXPECT_LT(angle_degrees(sync.implied[e], relative(G, m.from, m.to)), 3) << m.from << m.to;
    if (corrupted[e])
      EXPECT_GT(sync.disagreement_degrees[e], 150) << m.from << m.to;
    else
      EXPECT_LT(sync.disagreement_degrees[e], 6) << m.from << m.to;
  }
  for (const Eigen::Matrix3d& R : sync.global) EXPECT_NEAR(R.determinant(), 1, 1e-9);
}

TEST(SynchronizeRotations, ComponentsApartAndATreeKeepsItsMeasurements) {
  std::mt19937 random(3);
  std::vector<Eigen::Matrix3d> G;
  for (int a = 0; a < 8; ++a) G.push_back(test::random_rotation(200 + a));
  std::vector<RelativeRotation> measured;
  // Members 0-3: every pair, noisy; 4-6: a path (a tree); 7: alone.
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      measured.push_back({a, b, relative(G, a, b) * jitter(random, 3)});
  measured.push_back({4, 5, relative(G, 4, 5) * jitter(random, 30)});
  measured.push_back({6, 5, relative(G, 6, 5) * jitter(random, 30)});
  const SynchronizedRotations sync = synchronize_rotations(8, measured);
  for (size_t e = 0; e < measured.size(); ++e) {
    const RelativeRotation& m = measured[e];
    if (m.from < 4)
      EXPECT_LT(angle_degrees(sync.implied[e], relative(G, m.from, m.to)), 4);
    else  // no cycle: nothing to correct the measurement with
      EXPECT_LT(sync.disagreement_degrees[e], 1e-6);
  }
  EXPECT_LT(angle_degrees(sync.global[7], Eigen::Matrix3d::Identity()), 1e-9);
}

TEST(SynchronizeRotations, BadInputIsAUsageError) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  EXPECT_THROW(synchronize_rotations(3, {{0, 3, I}}), UsageError);
  EXPECT_THROW(synchronize_rotations(3, {{1, 1, I}}), UsageError);
  EXPECT_THROW(synchronize_rotations(3, {{0, 1, I}, {1, 0, I}}), UsageError);
  EXPECT_THROW(synchronize_rotations(3, {{0, 1, I}}, 0), UsageError);
}

}  // namespace
}  // namespace unfold
