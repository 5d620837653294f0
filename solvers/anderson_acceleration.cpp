#include "solvers/anderson_acceleration.h"

#include <Eigen/QR>
#include <algorithm>

namespace unfold {

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
  f_ = g - x;
  if (has_last_ && last_f_.size() == f_.size()) {
    newest_ = (newest_ + 1) % window_;
    count_ = std::min(count_ + 1, window_);
    dF_.col(newest_) = f_ - last_f_;
    dG_.col(newest_) = g - last_g_;
    for (int c = 0; c < count_; ++c)
      gram_(newest_, c) = gram_(c, newest_) = dF_.col(newest_).dot(dF_.col(c));
  } else {
    dF_.resize(f_.size(), window_);
    dG_.resize(f_.size(), window_);
    gram_.resize(window_, window_);
    count_ = 0;
    newest_ = -1;
  }
  has_last_ = true;
  last_f_ = f_;
  last_g_ = g;
  if (count_ == 0) return g;
  const Eigen::VectorXd rhs = dF_.leftCols(count_).transpose() * f_;
  const Eigen::VectorXd gamma =
      gram_.topLeftCorner(count_, count_).completeOrthogonalDecomposition().solve(rhs);
  return g - dG_.leftCols(count_) * gamma;
}

void AndersonAcceleration::reset() {
  has_last_ = false;
  count_ = 0;
  newest_ = -1;
}

}  // namespace unfold
