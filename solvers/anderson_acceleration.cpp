#include "solvers/anderson_acceleration.h"

#include <Eigen/QR>

namespace unfold {

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
  const Eigen::VectorXd f = g - x;
  if (last_f_.size() == f.size()) {
    dF_.push_back(f - last_f_);
    dG_.push_back(g - last_g_);
    if (int(dF_.size()) > window_) {
      dF_.pop_front();
      dG_.pop_front();
    }
  }
  last_f_ = f;
  last_g_ = g;
  if (dF_.empty()) return g;
  Eigen::MatrixXd dF(f.size(), Eigen::Index(dF_.size())), dG(f.size(), dF.cols());
  for (Eigen::Index k = 0; k < dF.cols(); ++k) {
    dF.col(k) = dF_[size_t(k)];
    dG.col(k) = dG_[size_t(k)];
  }
  const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(f);
  return g - dG * gamma;
}

void AndersonAcceleration::reset() {
  last_f_.resize(0);
  last_g_.resize(0);
  dF_.clear();
  dG_.clear();
}

}  // namespace unfold
