#include "metrics/edge_ratio.h"

namespace unfold {

double edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q) {
  double sum = 0;
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int i = graph.edges(e, 0), j = graph.edges(e, 1);
    sum += (Q.row(i) - Q.row(j)).norm() / (P.row(i) - P.row(j)).norm();
  }
  return graph.num_edges() > 0 ? sum / graph.num_edges() : 1.0;
}

}  // namespace unfold
