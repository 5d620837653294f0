#include "solvers/anderson_acceleration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace unfold {

void AndersonAcceleration::next(const Eigen::Ref<const Eigen::VectorXd>& x,
                                const Eigen::Ref<const Eigen::VectorXd>& g,
                                Eigen::Ref<Eigen::VectorXd> out) {
  const Eigen::Index n = x.size();
  f_ = g - x;
  if (has_last_ && last_f_.size() == n) {
    newest_ = (newest_ + 1) % window_;
    count_ = std::min(count_ + 1, window_);
    dF_.col(newest_) = f_ - last_f_;
    dG_.col(newest_) = g - last_g_;
    for (int s = 0; s < count_; ++s)
      gram_(newest_, s) = gram_(s, newest_) = dF_.col(newest_).dot(dF_.col(s));
  } else {
    dF_.resize(n, window_);
    dG_.resize(n, window_);
    gram_.resize(window_, window_);
    count_ = 0;
    newest_ = -1;
  }
  has_last_ = true;
  last_g_ = g;
  Eigen::VectorXd gamma = Eigen::VectorXd::Zero(count_);
  if (count_ > 0) {
    // Scaled to a unit diagonal, the Gram matrix's eigenvalues say which
    // combinations of differences are resolved; a zero difference (a repeated
    // step) has no scale and stays out.
    Eigen::VectorXd scale(count_);
    for (int s = 0; s < count_; ++s) scale(s) = gram_(s, s) > 0 ? 1 / std::sqrt(gram_(s, s)) : 0.0;
    const Eigen::MatrixXd C =
        scale.asDiagonal() * gram_.topLeftCorner(count_, count_) * scale.asDiagonal();
    const Eigen::VectorXd r = scale.asDiagonal() * (dF_.leftCols(count_).transpose() * f_);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(C);
    const Eigen::VectorXd& lambda = eigen.eigenvalues();
    const double cutoff = 1e-12 * std::max(lambda.maxCoeff(), 0.0);
    Eigen::VectorXd y = eigen.eigenvectors().transpose() * r;
    for (int s = 0; s < count_; ++s) y(s) = lambda(s) > cutoff ? y(s) / lambda(s) : 0.0;
    gamma = scale.asDiagonal() * (eigen.eigenvectors() * y);
  }
  last_f_.swap(f_);
  // What Eigen makes of out = g - dG gamma: g, then the product subtracted in place.
  out = g;
  if (count_ > 0) out.noalias() -= dG_.leftCols(count_) * gamma;
}

void AndersonAcceleration::reset() {
  has_last_ = false;
  count_ = 0;
  newest_ = -1;
}

}  // namespace unfold
