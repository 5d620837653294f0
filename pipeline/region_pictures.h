// Close-ups of one region of a shape and of its canonical form (issue 44:
// local detail that whole-body pictures are too small to judge): the
// --render_focus picture of unfold, and worst_<class>_<method>.png of a batch,
// every shape's worst region (metrics/worst_region.h) coloured by damage.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "pipeline/pose_invariance_tables.h"
#include "pipeline/result_pictures.h"
#include "render/close_up.h"

namespace unfold {

/// A close-up of the ball of `radius` about vertex `vertex` of V, seen face on:
/// along the area-weighted normal of the triangles with a corner in the ball
/// (when those cancel out, a closed part inside the ball, from the shape's
/// centroid towards the vertex), screen up near `up_axis` (view_facing).
/// @throws UsageError if vertex is outside V, or for a bad radius or up_axis
CloseUp region_close_up(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int vertex,
                        double radius, int up_axis);

/// The --render picture with --render_focus: the region about `vertex` (-1:
/// the worst region of result's damage; with kFolds the most folded vertex) on the input (left,
/// plainly shaded) and on the canonical form (right, coloured as `coloring`), each a close-up seen
/// face on. The region is the ball of region_radius(input, radius_fraction) on the input and of
/// that radius / damage.scale on the canonical form, so both show the same part at the input's
/// area. Damage is coloured from 0 to ln 3 (the damage bound, yellow: damaged), folds from 0 to 90
/// degrees (the fold bound), the rigidity error from 0 to its 98th percentile. Captions: the
/// vertex, and its worst edge ratio (with kFolds its fold).
/// @throws UsageError if vertex is outside the surface, the result has no
///         per-vertex damage (or folds, with kFolds), or for a bad radius_fraction or up_axis
Image render_region_before_after(const UnfoldResult& result, int vertex, double radius_fraction,
                                 int up_axis, SurfaceColoring coloring);

/// Writes output_dir/worst_<class>_<method>.png for every class and every
/// method label but "raw" (label 0) that has a form: per shape of the class,
/// the close-up of its form's worst region, coloured by damage from 0 to ln 3,
/// captioned with the shape's name and that worst edge ratio, and beside it
/// the same region of the input; and folds_<class>_<method>.png, the same
/// about each form's most folded vertex (metrics/surface_folds.h), coloured by
/// the sharpening of the bends from 0 to 90 degrees, captioned with its fold. A form whose damage
/// cannot be measured (a collapsed surface) gets a line in the log instead of tiles.
/// @param shapes as for write_pose_invariance_tables
/// @throws UsageError if a shape lacks its raw form or a label's entry,
///         OutputError if a file cannot be written
void write_worst_region_pictures(const std::string& output_dir,
                                 const std::vector<std::string>& labels,
                                 const std::vector<PoseShape>& shapes);

}  // namespace unfold
