// Pictures of unfolding results: before/after, and a beta sweep side by side.
#pragma once

#include <string>
#include <vector>

#include "pipeline/unfold_surface.h"
#include "render/render_comparison.h"

namespace unfold {

/// How render_before_after colours the canonical surface (--render_color).
enum class SurfaceColoring {
  kShading,   ///< plain shading
  kRigidity,  ///< each vertex's rigidity error (E_rig's term)
  kDamage,    ///< each vertex's edge damage: metrics.damage.per_vertex, the largest |ln r|
  kFolds,     ///< each vertex's fold: metrics.folds.per_vertex, its edges' largest sharpening
              ///< of bend (dihedral angle) in degrees (a surface crumpled with its lengths kept)
};

/// "shading", "rigidity", "damage" or "folds". @throws UsageError for another name
SurfaceColoring surface_coloring(const std::string& name);

/// The per-vertex values `coloring` paints the canonical surface with (empty
/// for kShading).
/// @throws UsageError if the result lacks them (no per-vertex damage or folds)
Eigen::VectorXd surface_coloring_values(const UnfoldResult& result, SurfaceColoring coloring);

/// The unfolded surface before (left half) and after (right half), side and top
/// views, same cameras and scale in both halves.
/// @param coloring colour the canonical surface by a per-vertex value (the
///        input stays plainly shaded)
/// @param draw_skeleton draw the curve skeleton over the input and the
///        straightened one over the canonical surface (method scf)
/// @throws UsageError for bad render options, or draw_skeleton without a skeleton
Image render_before_after(const UnfoldResult& result, const RenderOptions& options,
                          SurfaceColoring coloring = SurfaceColoring::kShading,
                          bool draw_skeleton = false);

/// The input surface, then one column per run of a beta sweep (unfold_beta_sweep),
/// titled with beta relative to n / lambda_2.
/// @param runs   results on the same surface; betas[k] is the factor of runs[k]
/// @throws UsageError if runs and betas differ in length or for bad render options
Image render_beta_sweep(const std::vector<UnfoldResult>& runs, const std::vector<double>& betas,
                        const RenderOptions& options);

}  // namespace unfold
