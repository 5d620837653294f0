#include "metrics/edge_ratio.h"

#include <string>

#include "core/errors.h"

namespace unfold {

double edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q) {
  if (P.rows() != graph.num_vertices || Q.rows() != graph.num_vertices)
    throw UsageError("edge_ratio: need P and Q with one row per graph vertex");
  if (graph.num_edges() == 0) throw InputError("edge_ratio: the graph has no edges");
  double sum = 0;
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int i = graph.edges(e, 0), j = graph.edges(e, 1);
    const double rest = (P.row(i) - P.row(j)).norm();
    if (rest == 0)
      throw InputError("edge_ratio: edge " + std::to_string(i) + "-" + std::to_string(j) +
                       " has zero rest length");
    sum += (Q.row(i) - Q.row(j)).norm() / rest;
  }
  return sum / graph.num_edges();
}

}  // namespace unfold
