// The solve's edges on the unfolded shape's tets (mesh/tet_and_surface_edge_graph.h)
// and what they change in the default: the surface's edges always present,
// no needle, and a surface with coincident vertices unfolds.
#include "mesh/tet_and_surface_edge_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "config/options.h"
#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"

namespace unfold {
namespace {

std::set<std::pair<int, int>> edge_set(const EdgeGraph& g) {
  std::set<std::pair<int, int>> s;
  for (int e = 0; e < g.num_edges(); ++e) s.insert({g.edges(e, 0), g.edges(e, 1)});
  return s;
}

// Two tets sharing the face 1 2 3; vertex 0 and 4 are the apexes.
Eigen::MatrixX3d bipyramid() {
  return (Eigen::MatrixX3d(5, 3) << 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, -1, 0, 0, 0, -1).finished();
}

TEST(TetAndSurfaceEdgeGraph, JoinsTheSurfaceEdgesTheTetsLeaveOut) {
  const Eigen::MatrixX3d P = bipyramid();
  // One tet only: the surface's edges 2-4, 3-4, 1-4 are in no tet.
  const Eigen::MatrixX4i T = (Eigen::MatrixX4i(1, 4) << 0, 1, 2, 3).finished();
  const Eigen::MatrixX3i F =
      (Eigen::MatrixX3i(6, 3) << 0, 1, 2, 0, 2, 3, 0, 3, 1, 4, 2, 1, 4, 3, 2, 4, 1, 3).finished();
  int zero = -1;
  std::vector<char> surface_only;
  const EdgeGraph g = tet_and_surface_edge_graph(P, T, F, &surface_only, &zero);
  EXPECT_EQ(zero, 0);
  const auto edges = edge_set(g);
  EXPECT_EQ(edges.size(), 9u);  // the tet's 6 and the three to the apex 4
  for (int i : {1, 2, 3}) EXPECT_TRUE(edges.count({i, 4})) << i;
  ASSERT_EQ(surface_only.size(), 9u);
  for (int e = 0; e < g.num_edges(); ++e)
    EXPECT_EQ(surface_only[size_t(e)], g.edges(e, 1) == 4) << g.edges(e, 0) << "-" << g.edges(e, 1);
  EXPECT_FALSE(edges.count({0, 4}));  // on no triangle and in no tet
  EXPECT_EQ(connected_components(g), 1);
}

TEST(TetAndSurfaceEdgeGraph, LeavesOutTetEdgesOfZeroLengthButNotTriangleEdges) {
  Eigen::MatrixX3d P = bipyramid();
  P.row(4) = P.row(0);  // the apexes coincide: the two tets' chord 0-4 has no length
  const Eigen::MatrixX3i F =
      (Eigen::MatrixX3i(6, 3) << 0, 1, 2, 0, 2, 3, 0, 3, 1, 4, 2, 1, 4, 3, 2, 4, 1, 3).finished();
  Eigen::MatrixX4i T04(1, 4);
  T04 << 0, 4, 1, 2;  // the chord 0-4 as a tet edge
  int zero = -1;
  const EdgeGraph g = tet_and_surface_edge_graph(P, T04, F, nullptr, &zero);
  EXPECT_EQ(zero, 1);
  EXPECT_FALSE(edge_set(g).count({0, 4}));
  // The same edge on a triangle is the input's own (degenerate) triangle: kept.
  Eigen::MatrixX3i F04 = F;
  F04.row(0) << 0, 4, 1;
  const EdgeGraph kept = tet_and_surface_edge_graph(P, T04, F04, nullptr, &zero);
  EXPECT_EQ(zero, 0);
  EXPECT_TRUE(edge_set(kept).count({0, 4}));
}

TEST(TetAndSurfaceEdgeGraph, RefusesCornersOutOfRange) {
  const Eigen::MatrixX3d P = bipyramid();
  const Eigen::MatrixX4i T = (Eigen::MatrixX4i(1, 4) << 0, 1, 2, 5).finished();
  const Eigen::MatrixX3i F = (Eigen::MatrixX3i(1, 3) << 0, 1, 2).finished();
  EXPECT_THROW(tet_and_surface_edge_graph(P, T, F), UsageError);
  const Eigen::MatrixX3i G = (Eigen::MatrixX3i(1, 3) << 0, 1, -1).finished();
  EXPECT_THROW(tet_and_surface_edge_graph(P, Eigen::MatrixX4i(0, 4), G), UsageError);
}

// Every 100th vertex of the demo animal gets a vertex two edges away moved
// onto it: coincident vertices that share no triangle, as remeshed scans have
// where two parts touch. The unfolded shape's Delaunay joins some of them.
SurfaceMesh animal_with_coincident_vertices() {
  SurfaceMesh s = make_articulated_shape(ShapePose::preset(0), 32);
  const EdgeGraph g = build_edge_graph(int(s.V.rows()), Eigen::MatrixXi(triangulate_faces(s)));
  std::set<int> moved;
  for (int i = 0; i < int(s.V.rows()); i += 100) {
    if (moved.count(i)) continue;
    std::set<int> ring1(g.neighbors.begin() + g.offsets[size_t(i)],
                        g.neighbors.begin() + g.offsets[size_t(i) + 1]);
    int j = int(s.V.rows());
    for (int a : ring1)
      for (int k = g.offsets[size_t(a)]; k < g.offsets[size_t(a) + 1]; ++k) {
        const int b = g.neighbors[size_t(k)];
        if (b != i && !ring1.count(b)) j = std::min(j, b);
      }
    s.V.row(j) = s.V.row(i);
    moved.insert(j);
  }
  return s;
}

TEST(TetAndSurfaceEdgeGraph, TheDefaultUnfoldsCoincidentVerticesTheTetsJoin) {
  const SurfaceMesh s = animal_with_coincident_vertices();
  Options without = Options();
  without.integrate.surface_edges = 0;
  // The case reproduces the failure of the tets' graph alone.
  EXPECT_THROW(unfold_surface(s, without), NumericalError);
  const UnfoldResult r = unfold_surface(s, Options());
  EXPECT_TRUE(std::isfinite(r.metrics.E_rig));
  EXPECT_TRUE(r.canonical.V.allFinite());
}

}  // namespace
}  // namespace unfold
