// Pictures of unfolding results: before/after, and a beta sweep side by side.
#pragma once

#include <vector>

#include "pipeline/unfold_surface.h"
#include "render/render_comparison.h"

namespace unfold {

/// The unfolded surface before (left half) and after (right half), side and top
/// views, same cameras and scale in both halves.
/// @param color_by_rigidity colour the canonical surface by each vertex's
///        rigidity error (E_rig's term; the input stays plainly shaded)
/// @param draw_skeleton draw the curve skeleton over the input and the
///        straightened one over the canonical surface (method scf)
/// @throws UsageError for bad render options, or draw_skeleton without a skeleton
Image render_before_after(const UnfoldResult& result, const RenderOptions& options,
                          bool color_by_rigidity = false, bool draw_skeleton = false);

/// The input surface, then one column per run of a beta sweep (unfold_beta_sweep),
/// titled with beta relative to n / lambda_2.
/// @param runs   results on the same surface; betas[k] is the factor of runs[k]
/// @throws UsageError if runs and betas differ in length or for bad render options
Image render_beta_sweep(const std::vector<UnfoldResult>& runs, const std::vector<double>& betas,
                        const RenderOptions& options);

}  // namespace unfold
