#include "energies/unfold_energy.h"

namespace unfold {

double unfold_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                     const Rotations& R, double beta, Eigen::MatrixX3d* grad) {
  Eigen::MatrixX3d grad_rigid;
  const double energy = stretch_energy(graph, Q, grad) +
                        beta * arap_energy(graph, P, Q, R, grad ? &grad_rigid : nullptr);
  if (grad) *grad += beta * grad_rigid;
  return energy;
}

}  // namespace unfold
