#include "energies/cotangent_weights.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>

namespace unfold {
namespace {

int edge_index(const EdgeGraph& g, int i, int j) {
  const auto begin = g.neighbors.begin() + g.offsets[size_t(i)];
  const auto end = g.neighbors.begin() + g.offsets[size_t(i) + 1];
  const auto it = std::lower_bound(begin, end, j);  // neighbour lists are ascending
  return g.neighbor_edge[size_t(it - g.neighbors.begin())];
}

}  // namespace

std::vector<double> cotangent_weights(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T,
                                      const EdgeGraph& graph) {
  std::vector<double> w(size_t(graph.num_edges()), 0.0);
  static const int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                  {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (const auto& p : pairs) {
      // Edge (a, b); opposite edge (c, d) with dihedral angle between faces acd and bcd.
      const int a = T(t, p[0]), b = T(t, p[1]), c = T(t, p[2]), d = T(t, p[3]);
      const Eigen::Vector3d cd = V.row(d) - V.row(c);
      const Eigen::Vector3d na = cd.cross(Eigen::Vector3d(V.row(a) - V.row(c)));
      const Eigen::Vector3d nb = cd.cross(Eigen::Vector3d(V.row(b) - V.row(c)));
      // na, nb point from cd towards a and b: their angle is the dihedral angle at cd.
      const double sine = na.cross(nb).norm();
      if (sine <= 0) continue;
      const double cot = na.dot(nb) / sine;
      w[size_t(edge_index(graph, std::min(a, b), std::max(a, b)))] += cd.norm() * cot / 6.0;
    }
  const double mean =
      std::accumulate(w.begin(), w.end(), 0.0) / double(std::max<size_t>(w.size(), 1));
  for (double& x : w) x = std::max(x, 1e-3 * std::abs(mean));
  return w;
}

}  // namespace unfold
