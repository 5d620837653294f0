#include "energies/energy_term.h"

#include "energies/residual_sum.h"

namespace unfold {

double EnergyTerm::evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                            Eigen::MatrixX3d* grad) const {
  ResidualSum sum(Q, scale, grad);
  const double value = add_residuals(Q, R, &sum);
  sum.finish();
  return scale * value;
}

}  // namespace unfold
