// The robust route's interior points: a lattice's points inside the surface,
// away from its vertices (tetra/tetrahedralize.h).
#pragma once

#include <Eigen/Core>

#include "tetra/fast_winding_number.h"

namespace unfold {

/// The interior grid is a cubic lattice sheared by this much: lattice point
/// (x, y, z) (in cells, in input order x, then y, then z) moves by
/// kInteriorGridShear * (y + z, x + z, x + y) cells. A cubic cell's 8 corners
/// are cospherical, which a Delaunay resolves by exact arithmetic and symbolic
/// perturbation (a third of TetGen's Delaunay time on the TOSCA/FAUST meshes),
/// each library its own way; a sheared cell has one Delaunay split, and with
/// this sign it is the one TetGen's perturbation picked for whole cells (the
/// robust route's Delaunay until it moved to CGAL): 6 tets around the
/// (1, 1, 1) diagonal (docs/tetrahedralization.md).
inline constexpr double kInteriorGridShear = -5e-7;

/// The cell centres of a cubic lattice of `spacing` over the box of tree.V whose
/// winding number (times `orientation`) is above 1/2 and which lie at least
/// spacing / 2 from every vertex of tree.V, in lattice order (x slowest, z fastest),
/// then sheared by kInteriorGridShear (both tests come first: the shear moves
/// no point across either).
///
/// Only the lattice points that can be inside are evaluated: on each line
/// along x, those from the first triangle's box the line crosses to the last.
/// Where the triangles have no boundary the winding number is an integer, 0
/// wherever a ray to infinity meets none of them; an open or misoriented
/// surface's boundary chain (mesh/boundary_chain.h) is closed in the argument
/// by a cone over each of its connected parts, and each part's box, grown until
/// the cones cannot lift a point beyond it to 1/2, is searched in full too. A
/// shape whose limbs point along the box's diagonals fills a few per cent of
/// its box (an unfolded david: 5.0M cells, 36k evaluated, 2.6k inside). The
/// points returned are those of evaluating every lattice point.
/// @param tree        fast_winding_number_precomputation of the surface
/// @param orientation 1 for an outward-oriented surface, -1 for an inward one
/// @param spacing     the lattice's cell size, positive
Eigen::MatrixX3d interior_grid_points(const FastWindingNumberTree& tree, double orientation,
                                      double spacing);

}  // namespace unfold
