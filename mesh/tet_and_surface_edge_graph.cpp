#include "mesh/tet_and_surface_edge_graph.h"

#include <string>
#include <vector>

#include "core/errors.h"

namespace unfold {

EdgeGraph tet_and_surface_edge_graph(const Eigen::MatrixX3d& P, const Eigen::MatrixX4i& T,
                                     const Eigen::MatrixX3i& F, std::vector<char>* surface_only,
                                     int* zero_length_dropped) {
  const int n = int(P.rows());
  const auto check = [n](const auto& cells, const char* what) {
    if (cells.size() > 0 && (cells.minCoeff() < 0 || cells.maxCoeff() >= n))
      throw UsageError(std::string("tet_and_surface_edge_graph: a corner of the ") + what +
                       " is not one of the " + std::to_string(n) + " vertices");
  };
  check(T, "tets");
  check(F, "triangles");
  const EdgeGraph tets = build_edge_graph(n, Eigen::MatrixXi(T));
  const EdgeGraph surface = build_edge_graph(n, Eigen::MatrixXi(F));
  // A surface edge of zero length is kept: the input's own degenerate
  // triangle, which the surface solve refuses with its own message.
  const auto joined = [](const EdgeGraph& g, int i, int j) {
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k)
      if (g.neighbors[size_t(k)] == j) return true;
    return false;
  };
  std::vector<Eigen::Vector2i> kept;
  kept.reserve(size_t(tets.num_edges() + surface.num_edges()));
  int dropped = 0;
  for (int e = 0; e < tets.num_edges(); ++e) {
    const int i = tets.edges(e, 0), j = tets.edges(e, 1);
    if ((P.row(i) - P.row(j)).squaredNorm() == 0 && !joined(surface, i, j))
      ++dropped;
    else
      kept.emplace_back(i, j);
  }
  for (int e = 0; e < surface.num_edges(); ++e) kept.push_back(surface.edges.row(e).transpose());
  Eigen::MatrixXi edges(Eigen::Index(kept.size()), 2);
  for (size_t e = 0; e < kept.size(); ++e) edges.row(Eigen::Index(e)) = kept[e].transpose();
  if (zero_length_dropped) *zero_length_dropped = dropped;
  EdgeGraph graph = build_edge_graph(n, edges);
  if (surface_only) {
    surface_only->assign(size_t(graph.num_edges()), 0);
    for (int e = 0; e < graph.num_edges(); ++e)
      (*surface_only)[size_t(e)] = !joined(tets, graph.edges(e, 0), graph.edges(e, 1));
  }
  return graph;
}

}  // namespace unfold
