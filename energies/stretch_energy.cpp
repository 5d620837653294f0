#include "energies/stretch_energy.h"

#include <cmath>

#include "core/errors.h"
#include "energies/difference_residual.h"
#include "energies/residual_sum.h"

namespace unfold {

StretchEnergy::StretchEnergy(std::shared_ptr<const EdgeGraph> graph, double weight,
                             Eigen::VectorXd masses)
    : QuadraticTerm(graph->num_vertices, weight, false),
      graph_(std::move(graph)),
      masses_(std::move(masses)) {
  if (masses_.size() == 0) return;
  if (masses_.size() != graph_->num_vertices)
    throw UsageError("stretch term: " + std::to_string(masses_.size()) + " masses for " +
                     std::to_string(graph_->num_vertices) + " vertices");
  if (!masses_.allFinite() || !(masses_.minCoeff() > 0))
    throw UsageError("stretch term: every vertex mass must be positive and finite");
  masses_ *= double(masses_.size()) / masses_.sum();
}

double StretchEnergy::add_residuals(const Eigen::MatrixX3d& Q, const Rotations& /*R*/,
                                    ResidualSum* sum) const {
  const int n = graph_->num_vertices;
  const SpreadResidual spread(masses_.size() ? (masses_.transpose() * Q).transpose() / n
                                             : Eigen::Vector3d(Q.colwise().mean().transpose()));
  double energy = 0;
  for (int i = 0; i < n; ++i) energy += sum->add<3, 1>(spread, {i}, -2.0 * n * mass(i));
  const DifferenceResidual edge;
  for (int e = 0; e < graph_->num_edges(); ++e) {
    const int a = graph_->edges(e, 0), b = graph_->edges(e, 1);
    energy += sum->add<3, 2>(edge, {a, b}, 2.0 * mass(a) * mass(b));
  }
  return energy;
}

void StretchEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  const int n = graph_->num_vertices;
  Eigen::VectorXd diagonal(n);
  for (int i = 0; i < n; ++i) diagonal[i] = -n * mass(i);
  for (int e = 0; e < graph_->num_edges(); ++e) {
    const int a = graph_->edges(e, 0), b = graph_->edges(e, 1);
    const double w = mass(a) * mass(b);
    diagonal[a] += w;
    diagonal[b] += w;
    H->emplace_back(a, b, -2.0 * scale * w);
    H->emplace_back(b, a, -2.0 * scale * w);
  }
  for (int i = 0; i < n; ++i) H->emplace_back(i, i, 2.0 * scale * diagonal[i]);
}

Eigen::VectorXd StretchEnergy::rank_one_hessian() const {
  return masses_.size() ? Eigen::VectorXd(std::sqrt(2.0) * masses_) : Eigen::VectorXd();
}

}  // namespace unfold
