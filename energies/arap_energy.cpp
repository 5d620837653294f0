#include "energies/arap_energy.h"

#include "energies/difference_residual.h"
#include "energies/residual_sum.h"
#include "geometry/row_major.h"

namespace unfold {

ArapEnergy::ArapEnergy(std::shared_ptr<const EdgeGraph> graph, const Eigen::MatrixX3d& rest,
                       std::vector<double> edge_weights, double weight)
    : QuadraticTerm(graph->num_vertices, weight, true),
      graph_(std::move(graph)),
      rest_(rest),
      weights_(std::move(edge_weights)),
      cells_(cell_rest_edges(*graph_, rest, weights_)) {}

double ArapEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& R,
                                 ResidualSum* sum) const {
  const EdgeGraph& g = *graph_;
  double energy = 0;
  for (int i = 0; i < g.num_vertices; ++i)
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      energy += sum->add<3, 2>(
          DifferenceResidual(R[size_t(i)] * (rest_.row(i) - rest_.row(j)).transpose()), {i, j},
          weights_[size_t(g.neighbor_edge[size_t(k)])]);
    }
  return energy;
}

void ArapEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (int e = 0; e < graph_->num_edges(); ++e) {
    const int i = graph_->edges(e, 0), j = graph_->edges(e, 1);
    const double w = 2.0 * scale * weights_[size_t(e)];
    H->emplace_back(i, i, w);
    H->emplace_back(j, j, w);
    H->emplace_back(i, j, -w);
    H->emplace_back(j, i, -w);
  }
}

void ArapEnergy::add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const {
  add_rotated_rest_edges(*graph_, cells_, R, scale, B);
}

void ArapEnergy::add_rotation_covariance(const Eigen::MatrixX3d& Q, double scale,
                                         std::vector<Eigen::Matrix3d>* S) const {
  add_cell_covariances(*graph_, cells_, Q, scale, S);
}

}  // namespace unfold
