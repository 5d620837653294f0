#include "energies/stretch_energy.h"

#include "energies/jet_evaluation.h"

namespace unfold {

double stretch_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& Q, Eigen::MatrixX3d* grad) {
  const int n = graph.num_vertices;
  // Row-major copy so each vertex is 3 contiguous doubles for the functors.
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> q = Q;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> g;
  if (grad) g.setZero(n, 3);
  auto grad_row = [&](int i) { return grad ? g.row(i).data() : nullptr; };

  const StretchSpreadResidual spread(Q.colwise().mean().transpose(), n);
  double energy = 0;
  for (int i = 0; i < n; ++i) energy -= squared_norm_1(spread, q.row(i).data(), -1.0, grad_row(i));
  const StretchEdgeResidual edge;
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int i = graph.edges(e, 0), j = graph.edges(e, 1);
    energy += squared_norm_2(edge, q.row(i).data(), q.row(j).data(), 1.0, grad_row(i), grad_row(j));
  }
  if (grad) *grad = g;
  return energy;
}

}  // namespace unfold
