#include "energies/user_pairs_energy.h"

#include "energies/difference_residual.h"
#include "energies/residual_sum.h"

namespace unfold {

double UserPairsEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                                      ResidualSum* sum) const {
  double energy = 0;
  for (const UserPair& p : pairs_) energy += sum->add<3, 2>(DifferenceResidual(p.t), {p.i, p.j});
  return energy;
}

}  // namespace unfold
