// Anderson acceleration of a fixed-point iteration x <- G(x) (type II, as in
// Peng et al. 2018, "Anderson Acceleration for Geometry Optimization and
// Physics Simulation"): the next iterate combines the last few images G(x_k)
// so that the combined residual G(x) - x is smallest. Local-global ARAP is
// such an iteration whose slow, low-frequency modes (a long body bending
// straight) this removes; the caller keeps it safe by checking the energy.
#pragma once

#include <Eigen/Core>

namespace unfold {

class AndersonAcceleration {
 public:
  /// @param window how many past steps are combined (m >= 1)
  explicit AndersonAcceleration(int window) : window_(window) {}

  /// The accelerated successor of x, given g = G(x): g itself on the first
  /// call after construction or reset(), then g - dG gamma with gamma the
  /// least-squares fit of the residual f = g - x by the last residual
  /// differences dF. gamma solves the normal equations dF^T dF gamma = dF^T f
  /// (window x window, complete orthogonal decomposition, so repeated steps do
  /// no harm), whose matrix gains one row and column a step: O(n window) a
  /// step, where a QR of dF would cost O(n window^2) and its copies.
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g);

  /// Forgets the past steps (e.g. after an extrapolation was rejected).
  void reset();

 private:
  int window_;
  bool has_last_ = false;
  int count_ = 0;    // columns of dF_, dG_ in use: the first count_
  int newest_ = -1;  // the newest one's column (they are a ring)
  Eigen::VectorXd f_, last_f_, last_g_;
  Eigen::MatrixXd dF_, dG_, gram_;  // n x window, n x window, dF_^T dF_
};

}  // namespace unfold
