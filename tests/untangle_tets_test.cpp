// Inverted tets are pushed back out by small moves of their corners, never
// farther than allowed, and a mesh with none inverted is left as it is.
#include "mesh/untangle_tets.h"

#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <random>

#include "config/options.h"
#include "core/errors.h"
#include "mesh/tet_volumes.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// The shortest edge at each vertex, of the tets and of the faces given.
Eigen::VectorXd shortest_edges(const Eigen::MatrixX3d& P, const Eigen::MatrixX4i& T,
                               const Eigen::MatrixXi& faces) {
  Eigen::VectorXd h = Eigen::VectorXd::Constant(P.rows(), std::numeric_limits<double>::infinity());
  const auto visit = [&](const auto& rows) {
    for (Eigen::Index r = 0; r < rows.rows(); ++r)
      for (Eigen::Index i = 0; i < rows.cols(); ++i)
        for (Eigen::Index j = 0; j < rows.cols(); ++j)
          if (i != j)
            h[rows(r, i)] = std::min(h[rows(r, i)], (P.row(rows(r, i)) - P.row(rows(r, j))).norm());
  };
  visit(T);
  visit(faces);
  return h;
}

// A sliver: its fourth corner 0.02 above the plane of the other three.
Eigen::MatrixX3d sliver() {
  Eigen::MatrixX3d P(4, 3);
  P << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 0.02;
  return P;
}

Eigen::MatrixX4i one_tet() {
  Eigen::MatrixX4i T(1, 4);
  T << 0, 1, 2, 3;
  return T;
}

TEST(UntangleTets, LeavesAMeshWithNoInvertedTetAsItIs) {
  const TetMesh grid = test::grid_tet_mesh(3, 3, 3);
  const Eigen::MatrixX3d turned = 1.5 * grid.V * test::random_rotation(7).transpose();
  Eigen::MatrixX3d Q = turned;
  const UntangleReport r = untangle_tets(grid.V, grid.V, grid.T, {30, 0.2}, &Q);
  EXPECT_EQ(r.inverted_before, 0);
  EXPECT_EQ(r.inverted_after, 0);
  EXPECT_EQ(r.moved_vertices, 0);
  EXPECT_EQ(r.sweeps, 0);
  EXPECT_EQ(Q, turned);
}

// The orientation is the one the tets were made with: mirrored tets made
// mirrored are upright there.
TEST(UntangleTets, TakesEachTetsOrientationFromWhereItWasMade) {
  Eigen::MatrixX3d mirrored = sliver();
  mirrored.col(0) *= -1;
  Eigen::MatrixX3d Q = mirrored;
  const UntangleReport r = untangle_tets(mirrored, sliver(), one_tet(), {30, 0.2}, &Q);
  EXPECT_EQ(r.inverted_before, 0);
  EXPECT_EQ(Q, mirrored);
}

TEST(UntangleTets, PushesAFlippedSliverBackOutByAFractionOfItsEdge) {
  const Eigen::MatrixX3d P = sliver();
  Eigen::MatrixX3d Q = P * test::random_rotation(3).transpose();
  Q.row(3) -= 0.03 * Eigen::RowVector3d(0, 0, 1) * test::random_rotation(3).transpose();
  ASSERT_LT(tet_volumes(Q, one_tet())[0], 0);
  const Eigen::MatrixX3d start = Q;
  const UntangleReport r = untangle_tets(P, P, one_tet(), {30, 0.2}, &Q);
  EXPECT_EQ(r.inverted_before, 1);
  EXPECT_EQ(r.inverted_after, 0);
  EXPECT_GT(tet_volumes(Q, one_tet())[0], 0);
  EXPECT_EQ(r.moved_vertices, 4);
  // The flip was 0.01 deep: the corners move about that, far less than an edge.
  EXPECT_LT((Q - start).rowwise().norm().maxCoeff(), 0.05);
  EXPECT_LE(r.largest_move, 0.2 + 1e-12);
}

TEST(UntangleTets, MovesNoVertexFartherThanAllowed) {
  const Eigen::MatrixX3d P = sliver();
  Eigen::MatrixX3d Q = P;
  Q(3, 2) = -0.5;  // deeply inverted: it cannot be mended within the bound
  const Eigen::MatrixX3d start = Q;
  Eigen::MatrixX3d frozen = Q;
  const UntangleReport none = untangle_tets(P, P, one_tet(), {30, 0.0}, &frozen);
  EXPECT_EQ(frozen, start);
  EXPECT_EQ(none.inverted_after, 1);

  const double bound = 0.05;
  const UntangleReport r = untangle_tets(P, P, one_tet(), {30, bound}, &Q);
  EXPECT_EQ(r.inverted_after, 1);
  EXPECT_EQ(r.sweeps, 30);
  const Eigen::VectorXd h = shortest_edges(P, one_tet(), Eigen::MatrixXi(0, 3));
  for (int i = 0; i < 4; ++i) EXPECT_LE((Q.row(i) - start.row(i)).norm(), bound * h[i] + 1e-12);
  EXPECT_GT(tet_volumes(Q, one_tet())[0], tet_volumes(start, one_tet())[0]);
}

// A face's edge shorter than the tets' bounds its ends' moves: vertex 3 has a
// face neighbour 0.01 away, so it may move 0.002 at most.
TEST(UntangleTets, AFacesShortEdgeBoundsTheMovesAtItsEnds) {
  Eigen::MatrixX3d P(5, 3);
  P << sliver(), 0.31, 0.3, 0.02;
  Eigen::MatrixXi faces(1, 3);
  faces << 0, 3, 4;
  Eigen::MatrixX3d Q = P;
  Q(3, 2) = -0.01;
  const Eigen::MatrixX3d start = Q;
  const UntangleReport r = untangle_tets(P, P, one_tet(), {30, 0.2}, &Q, &faces);
  EXPECT_EQ(r.inverted_after, 0);
  EXPECT_LE((Q.row(3) - start.row(3)).norm(), 0.2 * 0.01 + 1e-12);
  EXPECT_GT((Q.row(0) - start.row(0)).norm(), 0.002);  // the others take the move
  EXPECT_EQ(Q.row(4), start.row(4));                   // in no tet: never moved
}

// A grid whose vertices are jittered until tens of tets invert: every one is
// mended, and no vertex moves as far as the jitter did.
TEST(UntangleTets, MendsTheInvertedTetsOfAJitteredGrid) {
  const TetMesh grid = test::grid_tet_mesh(6, 6, 6);
  std::mt19937 rng(11);
  std::normal_distribution<double> jitter(0.0, 0.25);
  Eigen::MatrixX3d Q = grid.V;
  for (Eigen::Index i = 0; i < Q.size(); ++i) Q.data()[i] += jitter(rng);
  const Eigen::MatrixX3d start = Q;
  const int inverted = count_inverted_tets(grid.V, Q, grid.T);
  ASSERT_GT(inverted, 20);
  const UntangleReport r = untangle_tets(grid.V, grid.V, grid.T, {100, 0.5}, &Q);
  EXPECT_EQ(r.inverted_before, inverted);
  EXPECT_EQ(r.inverted_after, count_inverted_tets(grid.V, Q, grid.T));
  EXPECT_EQ(r.inverted_after, 0);
  EXPECT_LT((Q - start).rowwise().norm().maxCoeff(), 0.5);
  EXPECT_LT((Q - start).rowwise().norm().mean(), 0.25);
}

TEST(UntangleTets, RefusesMismatchedInputs) {
  const Eigen::MatrixX3d P = sliver();
  Eigen::MatrixX3d Q = P;
  Eigen::MatrixX3d short_rows = P.topRows(3);
  EXPECT_THROW(untangle_tets(P, short_rows, one_tet(), {30, 0.2}, &Q), UsageError);
  Eigen::MatrixX4i out_of_range = one_tet();
  out_of_range(0, 3) = 4;
  EXPECT_THROW(untangle_tets(P, P, out_of_range, {30, 0.2}, &Q), UsageError);
  EXPECT_THROW(untangle_tets(P, P, one_tet(), {-1, 0.2}, &Q), UsageError);
  EXPECT_THROW(untangle_tets(P, P, one_tet(), {30, std::nan("")}, &Q), UsageError);
  Eigen::MatrixXi faces(1, 3);
  faces << 0, 1, 7;
  EXPECT_THROW(untangle_tets(P, P, one_tet(), {30, 0.2}, &Q, &faces), UsageError);
}

// The default's last stage on the demo animal (closed mouth, a pose bent at
// every joint; resolution 48, whose rest surface is stored): the same solve
// with and without it, so every inverted tet it leaves was inverted before,
// and each vertex moved within its bound.
TEST(UntangleStage, TheDefaultMendsItsCanonicalTetsWithinTheBound) {
  const SurfaceMesh input = make_articulated_shape(ShapePose::closed_mouth(), 48);
  Options off;
  off.metrics = {};
  off.untangle.sweeps = 0;
  Options on = off;
  on.untangle.sweeps = Options().untangle.sweeps;
  const UnfoldResult before = unfold_surface(input, off), after = unfold_surface(input, on);
  ASSERT_GT(on.untangle.sweeps, 0);
  EXPECT_EQ(before.untangle.inverted_before, 0);  // off: no report
  EXPECT_EQ(after.untangle.inverted_before, before.metrics.inverted_tets);
  EXPECT_EQ(after.untangle.inverted_after, after.metrics.inverted_tets);
  EXPECT_GT(before.metrics.inverted_tets, 0);
  EXPECT_LT(after.metrics.inverted_tets, before.metrics.inverted_tets / 4);
  ASSERT_EQ(after.tets.T, before.tets.T);
  const Eigen::VectorXd h =
      shortest_edges(after.tets.V, after.tets.T, Eigen::MatrixXi(triangulate_faces(after.surface)));
  const Eigen::VectorXd moved = (after.tet_canonical - before.tet_canonical).rowwise().norm();
  EXPECT_GT(moved.maxCoeff(), 0);
  for (Eigen::Index i = 0; i < moved.size(); ++i)
    ASSERT_LE(moved[i], on.untangle.max_move * h[i] + 1e-9) << "vertex " << i;
  std::cout << "inverted tets " << before.metrics.inverted_tets << " -> "
            << after.metrics.inverted_tets << ", " << after.untangle.moved_vertices
            << " vertices moved\n";
}

}  // namespace
}  // namespace unfold
