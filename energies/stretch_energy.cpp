#include "energies/stretch_energy.h"

#include <cmath>

#include "core/errors.h"
#include "energies/difference_residual.h"
#include "energies/residual_sum.h"

namespace unfold {

StretchEnergy::StretchEnergy(std::shared_ptr<const EdgeGraph> graph, double weight,
                             Eigen::VectorXd masses, SpreadRegions regions)
    : QuadraticTerm(graph->num_vertices, weight, false),
      graph_(std::move(graph)),
      masses_(std::move(masses)),
      local_(regions.local) {
  if (masses_.size() > 0) {
    if (masses_.size() != graph_->num_vertices)
      throw UsageError("stretch term: " + std::to_string(masses_.size()) + " masses for " +
                       std::to_string(graph_->num_vertices) + " vertices");
    if (!masses_.allFinite() || !(masses_.minCoeff() > 0))
      throw UsageError("stretch term: every vertex mass must be positive and finite");
    masses_ *= double(masses_.size()) / masses_.sum();
  }
  region_mass_.setZero(regions.count);
  for (const auto& t : regions.weights) {
    if (t.row() < 0 || t.row() >= graph_->num_vertices || t.col() < 0 || t.col() >= regions.count)
      throw UsageError("stretch term: a region weight names a vertex or region out of range");
    region_mass_[t.col()] += mass(t.row()) * t.value();
  }
  weights_.resize(graph_->num_vertices, regions.count);
  weights_.setFromTriplets(regions.weights.begin(), regions.weights.end());
}

double StretchEnergy::add_residuals(const Eigen::MatrixX3d& Q, const Rotations& /*R*/,
                                    ResidualSum* sum) const {
  const int n = graph_->num_vertices;
  const SpreadResidual spread(masses_.size() ? (masses_.transpose() * Q).transpose() / n
                                             : Eigen::Vector3d(Q.colwise().mean().transpose()));
  double energy = 0;
  if (local_ == 0) {
    for (int i = 0; i < n; ++i) energy += sum->add<3, 1>(spread, {i}, -2.0 * n * mass(i));
  } else {
    // Each vertex's spread about its centres (c_m with weight 1 - t, c_k with
    // t w_ik) is its spread about their mean a_i plus their own spread about
    // a_i: one residual q_i - a_i a vertex (the same gradient and quadratic
    // form as one a centre, since every centroid is stationary) and a
    // constant. With chat = W c, sum_k w_ik |c_k - a_i|^2 = sum_k w_ik |c_k|^2
    // - 2 a_i . chat_i + |a_i|^2, and sum_i m_i sum_k w_ik |c_k|^2 = sum_k M_k |c_k|^2.
    Eigen::MatrixX3d mQ = masses_.size() ? Eigen::MatrixX3d(masses_.asDiagonal() * Q) : Q;
    Eigen::MatrixX3d c = weights_.transpose() * mQ;
    c.array().colwise() /= region_mass_.array();
    const Eigen::MatrixX3d chat = weights_ * c;
    const Eigen::RowVector3d cm = spread.c.transpose();
    double offset = local_ * (region_mass_.transpose() * c.rowwise().squaredNorm()).value();
    for (int i = 0; i < n; ++i) {
      const Eigen::RowVector3d a = (1.0 - local_) * cm + local_ * chat.row(i);
      const double own = (1.0 - local_) * (cm - a).squaredNorm() +
                         local_ * (a.squaredNorm() - 2.0 * a.dot(chat.row(i)));
      offset += mass(i) * own;
      energy += sum->add<3, 1>(SpreadResidual(a.transpose()), {i}, -2.0 * n * mass(i));
    }
    energy -= 2.0 * n * offset;
  }
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
  return masses_.size() ? Eigen::VectorXd(std::sqrt(2.0 * (1.0 - local_)) * masses_)
                        : Eigen::VectorXd();
}

Eigen::MatrixXd StretchEnergy::region_hessian() const {
  const int n = graph_->num_vertices;
  if (local_ == 0) return Eigen::MatrixXd(n, 0);
  Eigen::MatrixXd U = weights_;
  if (masses_.size()) U = masses_.asDiagonal() * U;
  return U * (2.0 * n * local_ * region_mass_.cwiseInverse()).cwiseSqrt().asDiagonal();
}

}  // namespace unfold
