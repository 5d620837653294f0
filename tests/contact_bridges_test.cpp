// Finding the tets that glue parts which only touch (tetrahedralize.shape: auto):
// none on poses without contact, those joining the crossed legs on a pose with
// contact, and no others.
#include "solvers/contact_bridges.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/errors.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"
#include "tetra/intersecting_faces.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

TEST(ContactBridges, NoneWhereNothingTouches) {
  for (int k = 0; k < ShapePose::num_presets(); ++k) {
    const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(k));
    const TetMesh tets = tetrahedralize(shape, TetOptions{});
    EXPECT_TRUE(tets_bridging_contact(shape, tets, 0.1).empty()) << "preset " << k;
  }
  const SurfaceMesh sphere = test::uv_sphere(12, 24);
  EXPECT_TRUE(tets_bridging_contact(sphere, tetrahedralize(sphere, TetOptions{}), 0.1).empty());
}

// The front legs passed through each other (contact pose 1): every tet with
// corners on both lower front legs is found (in the input's own tet mesh there
// are such tets), and what is found lies on the legs.
TEST(ContactBridges, FindsTheTetsJoiningCrossedLegs) {
  const SurfaceMesh crossed = make_articulated_shape(ShapePose::contact(1));
  const SurfaceMesh apart = make_articulated_shape(ShapePose::rest());
  const TetMesh tets = tetrahedralize(crossed, TetOptions{});
  const int ns = int(crossed.V.rows());
  // a surface vertex on a lower front leg (of the rest pose: below the knees, in front)
  const auto lower_front = [&](int i, double side) {
    return i < ns && apart.V(i, 2) < -0.9 && apart.V(i, 0) > 0.3 && apart.V(i, 1) * side > 0;
  };
  const std::vector<int> found = tets_bridging_contact(crossed, tets, 0.1);
  ASSERT_FALSE(found.empty());
  int joining = 0;
  for (int t = 0; t < tets.T.rows(); ++t) {
    bool left = false, right = false;
    for (int c = 0; c < 4; ++c) {
      left = left || lower_front(tets.T(t, c), 1);
      right = right || lower_front(tets.T(t, c), -1);
    }
    if (!(left && right)) continue;
    ++joining;
    EXPECT_TRUE(std::binary_search(found.begin(), found.end(), t)) << "tet " << t;
  }
  EXPECT_GT(joining, 0) << "the crossed legs' own tet mesh joins them";
  // Found tets have a corner on a front leg (or next to one: interior vertices).
  int on_legs = 0;
  for (const int t : found)
    for (int c = 0; c < 4; ++c)
      if (tets.T(t, c) < ns && apart.V(tets.T(t, c), 0) > 0.3 && apart.V(tets.T(t, c), 2) < -0.5) {
        ++on_legs;
        break;
      }
  EXPECT_GE(on_legs, 0.9 * double(found.size()));
}

// Stopping at the first bridge answers as listing them all does: on the poses
// without contact, on both contact poses, and at a reach so long that a pose
// with contact has none left.
TEST(ContactBridges, StoppingAtTheFirstBridgeAnswersAsListingThemAll) {
  std::vector<ShapePose> poses = {ShapePose::rest(), ShapePose::preset(1)};
  for (int k = 0; k < ShapePose::num_contact_poses(); ++k) poses.push_back(ShapePose::contact(k));
  int with_contact = 0;
  for (const ShapePose& pose : poses) {
    const SurfaceMesh shape = make_articulated_shape(pose);
    const TetMesh tets = tetrahedralize(shape, TetOptions{});
    for (const double reach : {0.1, 10.0}) {
      const bool listed = !tets_bridging_contact(shape, tets, reach).empty();
      EXPECT_EQ(some_tet_bridges_contact(shape, tets, reach), listed) << "reach " << reach;
      with_contact += listed;
    }
  }
  EXPECT_EQ(with_contact, ShapePose::num_contact_poses()) << "only the contact poses, at 0.1";
}

std::vector<std::pair<int, int>> intersections(const SurfaceMesh& surface) {
  return intersecting_face_pairs(surface.V, triangulate_faces(surface));
}

// The crossed legs pass through each other: their intersecting faces are far
// apart along the surface, and each such pair has a face on either front leg.
TEST(ContactBridges, IntersectionsOfCrossedLegsAreFarAlongTheSurface) {
  const SurfaceMesh crossed = make_articulated_shape(ShapePose::contact(1));
  const SurfaceMesh apart = make_articulated_shape(ShapePose::rest());
  const auto pairs = intersections(crossed);
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(count_intersections_far_along_surface(crossed, pairs, 0.1), int(pairs.size()));
  const Eigen::MatrixX3i F = triangulate_faces(crossed);
  const auto side = [&](int f) {  // of a face on a lower front leg of the rest pose: +-1, else 0
    const Eigen::RowVector3d c =
        (apart.V.row(F(f, 0)) + apart.V.row(F(f, 1)) + apart.V.row(F(f, 2))) / 3;
    return c(2) < -0.5 && c(0) > 0.3 ? (c(1) > 0 ? 1 : -1) : 0;
  };
  for (const auto& [s, t] : pairs) EXPECT_EQ(side(s) * side(t), -1) << s << ", " << t;
}

// An equator vertex dragged past its neighbour folds the faces around it over
// the next ones: a local defect, not contact. With a reach shorter than any
// edge, the pairs that share no corner count.
TEST(ContactBridges, NearbyIntersectionsAreNoContact) {
  SurfaceMesh folded = test::uv_sphere(24, 48);
  const auto equator = [](int s) { return 1 + 11 * 48 + s; };  // ring 12 of 23
  folded.V.row(equator(0)) = folded.V.row(equator(2));
  folded.V(equator(0), 2) += 0.01;
  const auto pairs = intersections(folded);
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(count_intersections_far_along_surface(folded, pairs, 0.1), 0);
  const Eigen::MatrixX3i F = triangulate_faces(folded);
  int apart = 0;
  for (const auto& [s, t] : pairs) {
    bool shared = false;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) shared = shared || F(s, a) == F(t, b);
    apart += !shared;
  }
  EXPECT_GT(apart, 0);
  EXPECT_EQ(count_intersections_far_along_surface(folded, pairs, 1e-4), apart);
  for (int k = 0; k < ShapePose::num_presets(); ++k) {
    const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(k));
    EXPECT_EQ(count_intersections_far_along_surface(shape, intersections(shape), 0.1), 0)
        << "preset " << k;
  }
}

TEST(ContactBridges, RefusesBadArguments) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::rest());
  const TetMesh tets = tetrahedralize(shape, TetOptions{});
  EXPECT_THROW(tets_bridging_contact(shape, tets, 0), UsageError);
  EXPECT_THROW(tets_bridging_contact(test::octahedron(), tets, 0.1), UsageError);
  EXPECT_THROW(some_tet_bridges_contact(shape, tets, -1), UsageError);
  EXPECT_THROW(some_tet_bridges_contact(test::octahedron(), tets, 0.1), UsageError);
  EXPECT_THROW(count_intersections_far_along_surface(shape, {}, 0), UsageError);
  const int faces = int(triangulate_faces(shape).rows());
  EXPECT_THROW(count_intersections_far_along_surface(shape, {{0, faces}}, 0.1), UsageError);
}

}  // namespace
}  // namespace unfold
