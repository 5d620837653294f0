// Stage: the integration's anchor unit (solvers/integrate_rotation_field.h).
#pragma once

#include "mesh/surface_mesh.h"

namespace unfold {

/// lambda_2 of the surface's uniform graph Laplacian. It depends on the
/// connectivity alone, so it is the same for every pose of a shape (the tet
/// mesh's is not) and for every arap.weight and arap.weights (the cascade's
/// lambda_2 is not).
/// @throws NumericalError when it cannot be found
double anchor_lambda2(const SurfaceMesh& surface);

}  // namespace unfold
