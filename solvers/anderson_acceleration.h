// Anderson acceleration of a fixed-point iteration x <- G(x) (type II, as in
// Peng et al. 2018, "Anderson Acceleration for Geometry Optimization and
// Physics Simulation"): the next iterate combines the last few images G(x_k)
// so that the combined residual G(x) - x is smallest. Local-global ARAP is
// such an iteration whose slow, low-frequency modes (a long body bending
// straight) this removes; the caller keeps it safe by checking the energy.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>

namespace unfold {

class AndersonAcceleration {
 public:
  /// @param window how many past steps are combined (m >= 1)
  explicit AndersonAcceleration(int window) : window_(window) {}

  /// Writes into out the accelerated successor of x, given g = G(x): g itself
  /// on the first call after construction or reset(), then g - dG gamma with
  /// gamma the least-squares fit of the residual f = g - x by the last residual
  /// differences dF (rank-revealing QR, so repeated steps do no harm). The
  /// differences and the QR keep their storage from step to step (fresh ones
  /// were 13 MB of new pages a step at 166k unknowns: docs/history/performance.md),
  /// and x, g and out are views, so that the callers' n x 3 positions need no copies.
  /// @param out the same size as x; may be x or g itself
  void next(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& g,
            Eigen::Ref<Eigen::VectorXd> out);

  /// Forgets the past steps (e.g. after an extrapolation was rejected).
  void reset();

 private:
  int window_;
  bool has_last_ = false;
  int count_ = 0;  // columns of dF_, dG_ in use, oldest first
  Eigen::VectorXd f_, last_f_, last_g_;
  Eigen::MatrixXd dF_, dG_;  // n x window
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

}  // namespace unfold
