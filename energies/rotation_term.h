// Capability of a term that depends on per-vertex rotations R_i, each only
// through cell i (vertex i and its neighbours) and linearly, as
//   e_t = -2 sum_i tr(R_i^T S_i(Q)^T) + (terms free of R):
// the local step minimises the summed rotation terms over every R_i by the best
// rotation of the summed covariances (fit_rotations, solvers/unfold_problem.h).
// A rotation term that is also quadratic has that R part as its whole linear
// part, -2 tr(Q^T B(R)) = -2 sum_i tr(R_i S_i(Q)), and a constant c(R): the
// local-global solver then takes the energy from the fitted covariances
// (energy_from_covariances, solvers/local_global.h).
// A term without this interface does not depend on R.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

class RotationTerm {
 public:
  virtual ~RotationTerm() = default;
  /// Adds scale * S_i(Q) into (*S)[i] for every cell i.
  /// @pre S holds n matrices
  virtual void add_rotation_covariance(const Eigen::MatrixX3d& Q, double scale,
                                       std::vector<Eigen::Matrix3d>* S) const = 0;
};

}  // namespace unfold
