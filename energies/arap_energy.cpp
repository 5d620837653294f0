#include "energies/arap_energy.h"

#include "energies/jet_evaluation.h"
#include "energies/row_major.h"

namespace unfold {

ArapEnergy::ArapEnergy(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                       std::vector<double> edge_weights, double weight)
    : EnergyTerm(weight, true),
      graph_(graph),
      rest_(rest),
      weights_(std::move(edge_weights)),
      weighted_laplacian_rest_(Eigen::MatrixX3d::Zero(rest.rows(), 3)) {
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int i = graph.edges(e, 0), j = graph.edges(e, 1);
    const Eigen::RowVector3d d = weights_[size_t(e)] * (rest.row(i) - rest.row(j));
    weighted_laplacian_rest_.row(i) += d;
    weighted_laplacian_rest_.row(j) -= d;
  }
}

double ArapEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                            Eigen::MatrixX3d* grad) const {
  ResidualSum sum(Q, scale, grad);
  double energy = 0;
  for (int i = 0; i < graph_.num_vertices; ++i)
    for (int k = graph_.offsets[size_t(i)]; k < graph_.offsets[size_t(i) + 1]; ++k) {
      const int j = graph_.neighbors[size_t(k)];
      const double w = weights_[size_t(graph_.neighbor_edge[size_t(k)])];
      energy += sum.add<3, 2>(
          ArapEdgeResidual(R[size_t(i)] * (rest_.row(i) - rest_.row(j)).transpose(), w), {i, j});
    }
  sum.finish();
  return energy;
}

void ArapEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (int e = 0; e < graph_.num_edges(); ++e) {
    const int i = graph_.edges(e, 0), j = graph_.edges(e, 1);
    const double w = 2.0 * scale * weights_[size_t(e)];
    H->emplace_back(i, i, w);
    H->emplace_back(j, j, w);
    H->emplace_back(i, j, -w);
    H->emplace_back(j, i, -w);
  }
}

void ArapEnergy::add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const {
#pragma omp parallel for schedule(static)
  for (int i = 0; i < graph_.num_vertices; ++i) {
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int k = graph_.offsets[size_t(i)]; k < graph_.offsets[size_t(i) + 1]; ++k) {
      const int j = graph_.neighbors[size_t(k)];
      const double w = weights_[size_t(graph_.neighbor_edge[size_t(k)])];
      b.noalias() +=
          w * ((R[size_t(i)] + R[size_t(j)]) * (rest_.row(i) - rest_.row(j)).transpose());
    }
    B->row(i) += scale * b.transpose();
  }
}

void ArapEnergy::add_rotation_covariance(const Eigen::MatrixX3d& Q, double scale,
                                         std::vector<Eigen::Matrix3d>* S) const {
#pragma omp parallel for schedule(static)
  for (int i = 0; i < graph_.num_vertices; ++i)
    for (int k = graph_.offsets[size_t(i)]; k < graph_.offsets[size_t(i) + 1]; ++k) {
      const int j = graph_.neighbors[size_t(k)];
      const double w = scale * weights_[size_t(graph_.neighbor_edge[size_t(k)])];
      (*S)[size_t(i)].noalias() +=
          w * (rest_.row(i) - rest_.row(j)).transpose() * (Q.row(i) - Q.row(j));
    }
}

}  // namespace unfold
