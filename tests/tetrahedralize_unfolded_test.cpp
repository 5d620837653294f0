// The tet mesh of the unfolded surface put back into the input
// (tetrahedralize.shape: unfolded): exact where the unfolded shape is a
// similarity of the input, and no tet joins parts the surface does not join.
#include "solvers/tetrahedralize_unfolded.h"

#include <gtest/gtest.h>

#include "core/errors.h"
#include "mesh/tet_quality.h"
#include "mesh/tet_volumes.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// An unfolded shape that is the input turned, moved and inflated 2.5 times:
// its tets put back into the input are those tets taken back by the same
// similarity, interior included, none inverted.
TEST(TetrahedralizeUnfolded, TakesASimilarityBackExactly) {
  const SurfaceMesh input = make_articulated_shape(ShapePose::preset(1));
  const Eigen::Matrix3d R = test::random_rotation(5);
  const Eigen::RowVector3d t(1, -2, 3);
  const Eigen::MatrixX3d S = (2.5 * input.V * R.transpose()).rowwise() + t;
  const UnfoldedTetMesh m = tetrahedralize_unfolded(input, S, TetOptions{});
  const int ns = int(input.V.rows());
  ASSERT_GT(m.rest.V.rows(), ns) << "the tet mesh has interior vertices";
  EXPECT_EQ(m.rest.num_surface_vertices, ns);
  EXPECT_EQ(m.rest.V.topRows(ns), input.V);
  EXPECT_EQ(m.unfolded.topRows(ns), S);
  const Eigen::MatrixX3d back = ((m.unfolded.rowwise() - t) * R) / 2.5;
  EXPECT_LT((m.rest.V - back).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_EQ(m.report.shape, "unfolded");
  EXPECT_EQ(m.report.inverted_rest_tets, 0);
  EXPECT_EQ(m.report.dropped_inverted_tets, 0);
}

// Two poses of the demo animal whose legs pass through each other: a tet mesh
// of the input has tets joining the two legs; the unfolded shape's has none,
// whatever the input. Here the "unfolded" shape is the rest pose, whose legs
// are apart: no tet may have corners on both front legs' lower halves.
TEST(TetrahedralizeUnfolded, JoinsNoPartsThatOnlyTouchInTheInput) {
  const SurfaceMesh crossed = make_articulated_shape(ShapePose::contact(1));
  const SurfaceMesh apart = make_articulated_shape(ShapePose::rest());
  // The lower front legs of the rest pose: below the knees, in front.
  const auto lower_front = [&](int i, double side) {
    return i < apart.V.rows() && apart.V(i, 2) < -0.9 && apart.V(i, 0) > 0.3 &&
           apart.V(i, 1) * side > 0;
  };
  const auto joins_legs = [&](const Eigen::MatrixX4i& T) {
    int count = 0;
    for (int k = 0; k < T.rows(); ++k) {
      bool left = false, right = false;
      for (int c = 0; c < 4; ++c) {
        left = left || lower_front(T(k, c), 1);
        right = right || lower_front(T(k, c), -1);
      }
      count += left && right;
    }
    return count;
  };
  const TetMesh joined = tetrahedralize(crossed, TetOptions{});
  EXPECT_GT(joins_legs(joined.T), 0) << "the crossed legs' own tet mesh joins them";
  const UnfoldedTetMesh m = tetrahedralize_unfolded(crossed, apart.V, TetOptions{});
  EXPECT_EQ(joins_legs(m.rest.T), 0);
  EXPECT_TRUE(m.rest.V.allFinite());
  // The report counts the tets left and the inverted ones among them.
  EXPECT_EQ(m.report.num_tets, m.rest.T.rows());
  EXPECT_EQ(count_inverted_tets(m.unfolded, m.rest.V, m.rest.T), m.report.inverted_rest_tets);
}

// The tets flat in the input are dropped as the inverted ones are, and counted:
// without the bound the same mesh keeps them; with it, what is left of them
// is what keeps the mesh connected (a few).
TEST(TetrahedralizeUnfolded, DropsTetsFlatInTheInput) {
  const SurfaceMesh crossed = make_articulated_shape(ShapePose::contact(1));
  const SurfaceMesh apart = make_articulated_shape(ShapePose::rest());
  TetOptions bounded;
  bounded.route = "robust";  // the route the pipeline takes for the unfolded shape
  bounded.unfolded_min_quality = 0.05;
  TetOptions all = bounded;
  all.unfolded_min_quality = 0;
  const UnfoldedTetMesh kept = tetrahedralize_unfolded(crossed, apart.V, all);
  EXPECT_EQ(kept.report.dropped_flat_tets, 0);
  const UnfoldedTetMesh m = tetrahedralize_unfolded(crossed, apart.V, bounded);
  const auto flat = [&](const UnfoldedTetMesh& mesh) {
    const Eigen::VectorXd q = tet_quality(mesh.rest.V, mesh.rest.T);
    return int((q.array() < bounded.unfolded_min_quality).count());
  };
  ASSERT_GT(flat(kept), 0) << "the demo's tets put back have flat ones";
  EXPECT_GT(m.report.dropped_flat_tets, 0);
  EXPECT_EQ(m.report.dropped_inverted_tets, kept.report.dropped_inverted_tets);
  EXPECT_EQ(m.report.num_tets + m.report.dropped_flat_tets, kept.report.num_tets);
  EXPECT_LT(flat(m), flat(kept) / 10);
}

TEST(TetrahedralizeUnfolded, RefusesAnUnfoldedShapeOfAnotherSize) {
  const SurfaceMesh input = make_articulated_shape(ShapePose::rest());
  EXPECT_THROW(tetrahedralize_unfolded(input, input.V.topRows(10), TetOptions{}), UsageError);
}

}  // namespace
}  // namespace unfold
