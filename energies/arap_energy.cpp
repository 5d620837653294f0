#include "energies/arap_energy.h"

#include "energies/jet_evaluation.h"

namespace unfold {

double arap_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                   const Rotations& R, Eigen::MatrixX3d* grad) {
  const int n = graph.num_vertices;
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> q = Q;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> g;
  if (grad) g.setZero(n, 3);
  auto grad_row = [&](int i) { return grad ? g.row(i).data() : nullptr; };

  double energy = 0;
  for (int i = 0; i < n; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const ArapEdgeResidual residual(R[size_t(i)] * (P.row(i) - P.row(j)).transpose());
      energy +=
          squared_norm_2(residual, q.row(i).data(), q.row(j).data(), 1.0, grad_row(i), grad_row(j));
    }
  if (grad) *grad = g;
  return energy;
}

}  // namespace unfold
