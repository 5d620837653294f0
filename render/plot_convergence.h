// The convergence plot of one run (the paper's Fig. 2e / 3f): energy and mean
// edge-length ratio per iteration, cascade boundaries marked.
#pragma once

#include <array>
#include <vector>

#include "render/image.h"
#include "solvers/cascade.h"

namespace unfold {

/// Two stacked line plots over the iterations of `history`: the energy (Eq. 3)
/// on top, the edge ratio below with the stopping band shaded; dashed vertical
/// lines where a new cascade (a larger beta) starts. Axes carry ticks and labels.
/// An empty history (no iteration was needed) gives a picture saying so.
/// @param band   the edge-ratio stopping band, drawn as a shaded strip
/// @throws UsageError for a size below 200 x 200 pixels
Image plot_convergence(const std::vector<IterationRecord>& history,
                       const std::array<double, 2>& band, int width = 720, int height = 520);

}  // namespace unfold
