// Tets that are inverted in the positions a mesh is used at, dropped. A tet
// mesh made on one shape and then given other rest positions (the unfolded
// shape's tets put back into the input, solvers/tetrahedralize_unfolded.h)
// has flat tets across the surface that turn inside out there: they have no
// rest shape to keep, and their edges pull the solve and the rigidity error
// towards nothing (docs/method.md, contact). So have tets that are nearly flat
// there (slivers of a Delaunay mesh, or flattened when put back): a small turn of
// a corner flips them.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// What drop_inverted_tets did.
struct DroppedTets {
  int inverted = 0;       ///< inverted tets dropped
  int flat = 0;           ///< upright tets flatter than the bound, dropped
  int kept_inverted = 0;  ///< inverted tets kept, as the parts need them
  int dropped() const { return inverted + flat; }
};

/// Removes the rows of T whose signed volume at `rest` does not have the sign
/// it has at `made` (count_inverted_tets' test), and those whose quality at
/// `rest` (tet_quality) is below `min_quality`, except those that joining
/// the rest needs: a dropped tet is put back, upright ones first, then the least
/// inverted (its volume ratio rest / made largest; ties in row order), when it joins
/// vertices the kept tets leave in different parts, so that the vertices stay
/// as connected as T had them (with `joined`: as T and `joined` together).
/// @param made positions T was made at (rows: vertices)
/// @param rest positions T is used at, the same size
/// @param T    tets (rows of corner indices), changed in place; the kept rows in order
/// @param joined optional rows of vertices joined otherwise (e.g. the surface's
///        triangles, when the solve has their edges): no tet is put back to join them
/// @param min_quality tets flatter than this at `rest` are dropped too; 0: only
///        inverted ones
/// @return the counts of what was dropped and kept
/// @throws UsageError if the positions' sizes differ, a corner is out of range or
///         min_quality is not in [0, 1]
DroppedTets drop_inverted_tets(const Eigen::MatrixX3d& made, const Eigen::MatrixX3d& rest,
                               Eigen::MatrixX4i* T, const Eigen::MatrixXi* joined = nullptr,
                               double min_quality = 0);

}  // namespace unfold
