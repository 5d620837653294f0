// Where a canonical form is damaged most: the region a close-up shows
// (issue 44: the worst shape and worst region beside the means).
#pragma once

#include <Eigen/Core>

#include "metrics/surface_damage.h"

namespace unfold {

/// The region's radius as a fraction of the input's bounding-box diagonal:
/// large enough to show the damage in its surroundings (a mouth, a paw),
/// small enough that the damage fills the picture; 1/16, a binary fraction,
/// so that the --render_focus_radius default reads as written.
constexpr double kRegionRadiusFraction = 0.0625;

/// The worst region of a form, centred on one surface vertex.
struct WorstRegion {
  int vertex = -1;    ///< the centre: the vertex with the most damaged edge
  double damage = 0;  ///< its damage: the largest |ln r| of its edges
  double ratio = 1;   ///< that edge's ratio r (> 1 stretched, < 1 crushed)
};

/// The vertex whose edges hold the largest damage (damage.per_vertex: the
/// most stretched or crushed edge of the whole surface has its ends there).
/// Ties, e.g. the two ends of that edge or a form with no damage at all, go to
/// the vertex whose 1-ring neighbours' damage sums higher (the more damaged
/// neighbourhood), then to the lower index: deterministic, and nothing tuned
/// to a shape.
/// @param damage surface_damage() of the form
/// @param F      the faces it was measured on (m x k, k >= 3): they give the 1-rings
/// @throws UsageError if damage has no per-vertex values or F indexes outside them
WorstRegion worst_region(const SurfaceDamage& damage, const Eigen::MatrixXi& F);

/// fraction * the bounding-box diagonal of V: the radius of a region on the
/// input; on the canonical form the same region has radius / damage.scale
/// (the form's lengths at the input's area).
/// @throws UsageError if fraction is not in (0, 1] or V is empty
double region_radius(const Eigen::MatrixX3d& V, double fraction = kRegionRadiusFraction);

}  // namespace unfold
