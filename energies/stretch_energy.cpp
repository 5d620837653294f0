#include "energies/stretch_energy.h"

#include "energies/difference_residual.h"
#include "energies/residual_sum.h"

namespace unfold {

double StretchEnergy::add_residuals(const Eigen::MatrixX3d& Q, const Rotations& /*R*/,
                                    ResidualSum* sum) const {
  const int n = graph_->num_vertices;
  const SpreadResidual spread(Q.colwise().mean().transpose());
  double energy = 0;
  for (int i = 0; i < n; ++i) energy += sum->add<3, 1>(spread, {i}, -2.0 * n);
  const DifferenceResidual edge;
  for (int e = 0; e < graph_->num_edges(); ++e)
    energy += sum->add<3, 2>(edge, {graph_->edges(e, 0), graph_->edges(e, 1)}, 2.0);
  return energy;
}

void StretchEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (int i = 0; i < graph_->num_vertices; ++i)
    H->emplace_back(i, i, scale * 2.0 * (graph_->degree(i) - graph_->num_vertices));
  for (int e = 0; e < graph_->num_edges(); ++e) {
    H->emplace_back(graph_->edges(e, 0), graph_->edges(e, 1), -2.0 * scale);
    H->emplace_back(graph_->edges(e, 1), graph_->edges(e, 0), -2.0 * scale);
  }
}

}  // namespace unfold
