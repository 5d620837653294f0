#include "energies/user_pairs_energy.h"

#include "energies/difference_residual.h"
#include "energies/residual_sum.h"

namespace unfold {

void UserPairsEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                                    ResidualSum* sum) const {
  for (const UserPair& p : pairs_) sum->add<3, 2>(DifferenceResidual(p.t), {p.i, p.j});
}

}  // namespace unfold
