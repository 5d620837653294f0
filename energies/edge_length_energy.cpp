#include "energies/edge_length_energy.h"

#include "energies/residual_sum.h"

namespace unfold {

EdgeLengthEnergy::EdgeLengthEnergy(std::shared_ptr<const EdgeGraph> graph,
                                   const Eigen::MatrixX3d& rest, double weight)
    : EnergyTerm(weight, true), graph_(std::move(graph)), rest_length_(graph_->num_edges()) {
  for (int e = 0; e < graph_->num_edges(); ++e)
    rest_length_[e] = (rest.row(graph_->edges(e, 0)) - rest.row(graph_->edges(e, 1))).norm();
}

double EdgeLengthEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                                       ResidualSum* sum) const {
  double energy = 0;
  for (int e = 0; e < graph_->num_edges(); ++e)
    energy += sum->add<1, 2>(EdgeLengthResidual(rest_length_[e]),
                             {graph_->edges(e, 0), graph_->edges(e, 1)}, 2.0);
  return energy;
}

void EdgeLengthEnergy::add_growth_hessian(double scale,
                                          std::vector<Eigen::Triplet<double>>* H) const {
  for (int e = 0; e < graph_->num_edges(); ++e) {
    const int i = graph_->edges(e, 0), j = graph_->edges(e, 1);
    H->emplace_back(i, i, 2.0 * scale);
    H->emplace_back(j, j, 2.0 * scale);
    H->emplace_back(i, j, -2.0 * scale);
    H->emplace_back(j, i, -2.0 * scale);
  }
}

}  // namespace unfold
