// An edge graph renumbered (mesh/permute_edge_graph.h) is the graph of the
// renumbered tets, and its edge order says where each edge was.
#include "mesh/permute_edge_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "core/errors.h"
#include "test_meshes.h"

namespace unfold {
namespace {

TEST(PermuteEdgeGraph, IsTheGraphOfTheRenumberedTets) {
  const TetMesh mesh = test::grid_tet_mesh(5, 4, 3);
  const int n = int(mesh.V.rows());
  const EdgeGraph g = build_edge_graph(n, mesh.T);
  std::vector<int> order(static_cast<size_t>(n)), new_of(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  for (int i = 0; i < n; ++i) new_of[size_t(order[size_t(i)])] = i;
  Eigen::MatrixXi T = mesh.T;
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int c = 0; c < 4; ++c) T(t, c) = new_of[size_t(T(t, c))];
  std::vector<int> edge_order;
  const EdgeGraph p = permute_edge_graph(g, order, &edge_order);
  const EdgeGraph expected = build_edge_graph(n, T);
  EXPECT_EQ(p.num_vertices, n);
  EXPECT_TRUE(p.edges == expected.edges);
  EXPECT_EQ(p.offsets, expected.offsets);
  EXPECT_EQ(p.neighbors, expected.neighbors);
  EXPECT_EQ(p.neighbor_edge, expected.neighbor_edge);
  ASSERT_EQ(edge_order.size(), size_t(g.num_edges()));
  for (int e = 0; e < p.num_edges(); ++e) {
    const int old = edge_order[size_t(e)];
    const int a = order[size_t(p.edges(e, 0))], b = order[size_t(p.edges(e, 1))];
    EXPECT_EQ(std::min(a, b), g.edges(old, 0));
    EXPECT_EQ(std::max(a, b), g.edges(old, 1));
  }
}

TEST(PermuteEdgeGraph, RefusesWhatIsNotAPermutation) {
  const TetMesh mesh = test::grid_tet_mesh(3, 2, 2);
  const EdgeGraph g = build_edge_graph(int(mesh.V.rows()), mesh.T);
  std::vector<int> order(size_t(g.num_vertices));
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> twice = order;
  twice[1] = 0;
  EXPECT_THROW(permute_edge_graph(g, twice), UsageError);
  order.pop_back();
  EXPECT_THROW(permute_edge_graph(g, order), UsageError);
}

}  // namespace
}  // namespace unfold
