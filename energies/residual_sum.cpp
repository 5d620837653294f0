#include "energies/residual_sum.h"

#include "core/errors.h"

namespace unfold {

void ResidualSum::throw_anisotropic() {
  throw UsageError(
      "a residual's Jacobian does not act alike on x, y and z: the term has no n x n quadratic "
      "form (derive it from EnergyTerm, not QuadraticTerm)");
}

}  // namespace unfold
