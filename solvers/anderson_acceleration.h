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

  /// Writes into out the accelerated successor of x, given g = G(x): g itself
  /// on the first call after construction or reset(), then g - dG gamma with
  /// gamma the least-squares fit of the residual f = g - x by the last residual
  /// differences dF. The fit solves the normal equations dF^T dF gamma = dF^T f,
  /// their Gram matrix kept from step to step (a new difference adds one row
  /// of dot products), the columns scaled to unit length and directions the
  /// window does not resolve (relative eigenvalue below 1e-12: repeated steps)
  /// left out. The differences live in a ring, so nothing is copied as the
  /// window slides; x, g and out are views, so the callers' n x 3 positions
  /// need no copies. A step costs about 4 window n flops, against the 2
  /// window^2 n of a QR of dF (docs/performance.md, Anderson).
  /// @param out the same size as x; may be x or g itself
  void next(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& g,
            Eigen::Ref<Eigen::VectorXd> out);

  /// Forgets the past steps (e.g. after an extrapolation was rejected).
  void reset();

 private:
  int window_;
  bool has_last_ = false;
  int count_ = 0;    // differences held: ring slots [0, count_)
  int newest_ = -1;  // the slot of the newest difference
  Eigen::VectorXd f_, last_f_, last_g_;
  Eigen::MatrixXd dF_, dG_;  // n x window, a ring
  Eigen::MatrixXd gram_;     // window x window: dF_^T dF_ over the held slots
};

}  // namespace unfold
