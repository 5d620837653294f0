#include "solvers/unbend_skeleton.h"

#include <queue>
#include <string>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "solvers/lsmds.h"

namespace unfold {

UnbentSkeleton unbend_skeleton(const Eigen::MatrixX3d& nodes, const Eigen::MatrixX2i& edges,
                               int max_iterations, double tolerance) {
  const int n = int(nodes.rows());
  if (edges.size() > 0 && (edges.minCoeff() < 0 || edges.maxCoeff() >= n))
    throw UsageError("unbend_skeleton: a bone names a node that does not exist");
  const EdgeGraph graph = build_edge_graph(n, Eigen::MatrixXi(edges));
  if (n < 2 || connected_components(graph) != 1)
    throw NumericalError("scf: the skeleton is disconnected or has fewer than two nodes");
  LsmdsOptions mds;
  mds.exact_limit = n;  // a skeleton is small: all pairs
  mds.max_iterations = max_iterations;
  mds.tolerance = tolerance;
  const LandmarkDistances distances = lsmds_distances(graph, nodes, mds);
  const LsmdsResult smacof_result = smacof(distances, nodes, mds);

  UnbentSkeleton u;
  u.distances = distances.rows;
  u.stress = smacof_result.stress.back();
  u.iterations = smacof_result.iterations;
  Eigen::Index root = 0;
  u.distances.rowwise().maxCoeff().minCoeff(&root);
  u.parent.assign(size_t(n), -1);
  std::vector<bool> seen(size_t(n), false);
  std::queue<int> queue;
  queue.push(int(root));
  seen[size_t(root)] = true;
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop();
    u.order.push_back(i);
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      if (seen[size_t(j)]) continue;
      seen[size_t(j)] = true;
      u.parent[size_t(j)] = i;
      queue.push(j);
    }
  }
  // MDS fixes the shape up to a rigid motion: put it back near the rest nodes.
  const Eigen::MatrixX3d& X = smacof_result.positions;
  u.nodes.resize(n, 3);
  u.nodes.row(root) = X.row(root) + nodes.colwise().mean();
  for (size_t k = 1; k < u.order.size(); ++k) {
    const int c = u.order[k], p = u.parent[size_t(c)];
    Eigen::RowVector3d direction = X.row(c) - X.row(p);
    if (direction.norm() == 0) direction = nodes.row(c) - nodes.row(p);
    u.nodes.row(c) = u.nodes.row(p) + (nodes.row(c) - nodes.row(p)).norm() * direction.normalized();
  }
  return u;
}

}  // namespace unfold
