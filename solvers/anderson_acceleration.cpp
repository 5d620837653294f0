#include "solvers/anderson_acceleration.h"

#include <algorithm>

namespace unfold {

void AndersonAcceleration::next(const Eigen::Ref<const Eigen::VectorXd>& x,
                                const Eigen::Ref<const Eigen::VectorXd>& g,
                                Eigen::Ref<Eigen::VectorXd> out) {
  f_ = g - x;
  const Eigen::Index n = f_.size();
  if (has_last_ && last_f_.size() == n) {
    if (count_ == window_) {  // drop the oldest: the others one column left
      std::copy(dF_.data() + n, dF_.data() + n * window_, dF_.data());
      std::copy(dG_.data() + n, dG_.data() + n * window_, dG_.data());
    } else {
      ++count_;
    }
    dF_.col(count_ - 1) = f_ - last_f_;
    dG_.col(count_ - 1) = g - last_g_;
  } else {
    dF_.resize(n, window_);
    dG_.resize(n, window_);
    count_ = 0;
  }
  has_last_ = true;
  last_f_ = f_;
  last_g_ = g;
  if (count_ == 0) {
    out = g;
    return;
  }
  qr_.compute(dF_.leftCols(count_));
  const Eigen::VectorXd gamma = qr_.solve(f_);
  // What Eigen makes of out = g - dG gamma: g, then the product subtracted in place.
  out = g;
  out.noalias() -= dG_.leftCols(count_) * gamma;
}

void AndersonAcceleration::reset() {
  has_last_ = false;
  count_ = 0;
}

}  // namespace unfold
