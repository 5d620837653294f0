// Stage: tetrahedralize.shape unfolded. The tet mesh of the surface solve's
// shape S, its interior put back into the input (solvers/tetrahedralize_unfolded.h):
// parts that touch in the input are joined by no tet.
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

struct UnfoldedShapeTets {
  TetMesh rest;  ///< the tets, at rest: the input's surface, the interior placed into it
  Eigen::MatrixX3d unfolded;   ///< rest's vertices where the tets were made (in S)
  Eigen::MatrixX3d positions;  ///< unfolded, zero mean: the solve's positions from here on
  TetReport report;
};

/// Tetrahedralizes S (route auto taken as robust: S may or may not intersect
/// itself somewhere, and one route for every pose keeps the poses' tets alike).
/// @param surface       the input surface
/// @param S             the surface solve's positions of surface's vertices
/// @param surface_edges_join  the integration's steps will join the surface's edges
/// @throws NumericalError when S cannot be tetrahedralized
UnfoldedShapeTets tets_of_unfolded_shape(const SurfaceMesh& surface, const Eigen::MatrixX3d& S,
                                         TetOptions tet, bool surface_edges_join);

}  // namespace unfold
