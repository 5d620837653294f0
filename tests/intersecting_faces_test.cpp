// Self-intersection counting: crossing, touching and overlapping triangles
// count, what adjacent triangles share does not, the grid finds every pair an
// all-pairs search finds, and the count reaches the tetrahedralization report.
#include "tetra/intersecting_faces.h"

#include <gtest/gtest.h>

#include <random>

#include "core/errors.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

// Two triangles, the first at corners 0-2, the second at corners 3-5.
Pairs pairs_of(const Eigen::Matrix<double, 6, 3>& corners) {
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  return intersecting_face_pairs(corners, F);
}

TEST(IntersectingFaces, CrossingTrianglesCountOnce) {
  Eigen::Matrix<double, 6, 3> V;
  V << 0, 0, 0, 2, 0, 0, 0, 2, 0,          // in the plane z = 0
      0.5, 0.5, -1, 0.5, 0.5, 1, 3, 3, 0;  // pierces it at (0.5, 0.5, 0)
  EXPECT_EQ(pairs_of(V), Pairs({{0, 1}}));
  V.bottomRows(3) << 1.5, 1.5, -1, 1.5, 1.5, 1, 3, 3, 0;  // crosses the plane where x + y > 2
  EXPECT_TRUE(pairs_of(V).empty());
}

TEST(IntersectingFaces, TouchingCountsAndNearMissesDoNot) {
  Eigen::Matrix<double, 6, 3> V;
  V << 0, 0, 0, 2, 0, 0, 0, 2, 0,         //
      0.5, 0.5, 0, 0.5, 0.5, 1, 1, 2, 1;  // a corner on the first triangle's face
  EXPECT_EQ(pairs_of(V).size(), 1u);
  V.row(3) << 0.5, 0.5, 1e-30;  // just above it: exact predicates see the gap
  EXPECT_TRUE(pairs_of(V).empty());
}

TEST(IntersectingFaces, CoplanarOverlapCountsAndDisjointCoplanarDoesNot) {
  Eigen::Matrix<double, 6, 3> V;
  V << 0, 0, 0, 2, 0, 0, 0, 2, 0,  //
      0.5, 0.5, 0, 3, 0.5, 0, 0.5, 3, 0;
  EXPECT_EQ(pairs_of(V).size(), 1u);
  V.bottomRows(3) << 1.5, 1.5, 0, 3, 1.5, 0, 1.5, 3, 0;  // beyond x + y = 2, boxes overlapping
  EXPECT_TRUE(pairs_of(V).empty());
}

TEST(IntersectingFaces, NeighboursIntersectOnlyBeyondWhatTheyShare) {
  Eigen::MatrixX3d V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, -1, -1, 0.5;
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 1, 3, 2;  // a flat pair across edge 1-2
  EXPECT_TRUE(intersecting_face_pairs(V, F).empty());
  F << 0, 1, 2, 1, 2, 4;  // a bent pair across edge 1-2
  EXPECT_TRUE(intersecting_face_pairs(V, F).empty());
  F << 0, 1, 2, 0, 4, 5;  // a fan touching at vertex 0 only
  EXPECT_TRUE(intersecting_face_pairs(V, F).empty());
  V.row(3) << 0.2, 0.2, 0;  // folded onto its neighbour across edge 1-2
  F << 0, 1, 2, 1, 3, 2;
  EXPECT_EQ(intersecting_face_pairs(V, F).size(), 1u);
  V.row(5) << 0.3, 0.3, -1;  // sharing vertex 0 and passing through the other
  V.row(4) << 0.3, 0.3, 1;
  F << 0, 1, 2, 0, 4, 5;
  EXPECT_EQ(intersecting_face_pairs(V, F).size(), 1u);
}

TEST(IntersectingFaces, VerticesAtEqualPositionsAreShared) {
  // The bent pair again, but the second triangle has its own copies of the
  // shared edge's corners: still only the edge in common.
  Eigen::MatrixX3d V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  EXPECT_TRUE(intersecting_face_pairs(V, F).empty());
  V.row(5) << 0, 0, 0;  // the same triangle twice, under other indices
  EXPECT_EQ(intersecting_face_pairs(V, F).size(), 1u);
}

TEST(IntersectingFaces, ACleanSphereHasNone) {
  const SurfaceMesh sphere = test::uv_sphere(24, 48);
  EXPECT_TRUE(intersecting_face_pairs(sphere.V, triangulate_faces(sphere)).empty());
  const SurfaceMesh animal = make_articulated_shape(ShapePose::rest(), 32);
  EXPECT_TRUE(intersecting_face_pairs(animal.V, triangulate_faces(animal)).empty());
}

TEST(IntersectingFaces, LegsPushedThroughEachOtherIntersect) {
  const SurfaceMesh rest = make_articulated_shape(ShapePose::rest(), 32);
  ShapePose pose;
  pose.front_left.hip_spread = pose.front_right.hip_spread = -20;
  const SurfaceMesh crossed = make_articulated_shape(pose, 32);
  const Eigen::MatrixX3i F = triangulate_faces(crossed);
  const Pairs pairs = intersecting_face_pairs(crossed.V, F);
  ASSERT_FALSE(pairs.empty());
  // Every pair is one triangle of each lower front leg (picked in the rest
  // pose: left +y, right -y).
  const double low = rest.V.col(2).minCoeff(), high = rest.V.col(2).maxCoeff();
  const auto side = [&](int t) {
    int left = 0, right = 0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = rest.V.row(F(t, k));
      if (p(2) < low + 0.5 * (high - low) && p(0) > 0) (p(1) > 0 ? left : right)++;
    }
    return left == 3 ? 1 : right == 3 ? -1 : 0;
  };
  for (const auto& [s, t] : pairs) EXPECT_EQ(side(s) * side(t), -1) << s << " " << t;
}

TEST(IntersectingFaces, GridFindsWhatAllPairsFind) {
  // A soup of random small triangles, dense enough to cross often.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const int num = 150;
  Eigen::MatrixX3d V(3 * num, 3);
  Eigen::MatrixX3i F(num, 3);
  for (int t = 0; t < num; ++t) {
    const Eigen::RowVector3d center(unit(random), unit(random), unit(random));
    for (int k = 0; k < 3; ++k) {
      V.row(3 * t + k) =
          center + 0.3 * Eigen::RowVector3d(unit(random), unit(random), unit(random));
      F(t, k) = 3 * t + k;
    }
  }
  Pairs all;
  for (int s = 0; s < num; ++s)
    for (int t = s + 1; t < num; ++t) {
      Eigen::Matrix<double, 6, 3> corners;
      corners << V.middleRows(3 * s, 3), V.middleRows(3 * t, 3);
      if (!pairs_of(corners).empty()) all.emplace_back(s, t);
    }
  EXPECT_GT(all.size(), 20u);
  EXPECT_EQ(intersecting_face_pairs(V, F), all);
}

TEST(IntersectingFaces, BadIndexIsAUsageError) {
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 1, 2, 3;
  EXPECT_THROW(intersecting_face_pairs(Eigen::MatrixX3d::Zero(3, 3), F), UsageError);
}

TEST(IntersectingFaces, TheTetReportCountsThem) {
  TetReport report;
  tetrahedralize(test::two_interpenetrating_octahedra(), TetOptions{}, &report);
  EXPECT_EQ(report.route, "robust");
  const SurfaceMesh octahedra = test::two_interpenetrating_octahedra();
  EXPECT_EQ(report.num_intersecting_faces,
            int(intersecting_face_pairs(octahedra.V, triangulate_faces(octahedra)).size()));
  EXPECT_GT(report.num_intersecting_faces, 0);
  tetrahedralize(test::uv_sphere(8, 12), TetOptions{}, &report);
  EXPECT_EQ(report.num_intersecting_faces, 0);
}

}  // namespace
}  // namespace unfold
