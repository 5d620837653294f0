// Accuracy/cost knobs of the metrics: exact sums up to a size, estimates above.
#pragma once

namespace unfold {

struct MetricsOptions {
  int stretch_exact_limit = 20000;     ///< E_str over all pairs up to this many vertices
  int stretch_samples = 2000000;       ///< random pairs for E_str above the limit
  int geodesic_exact_limit = 3000;     ///< E_geo from all-pairs geodesics up to this size
  int geodesic_landmarks = 256;        ///< geodesic source vertices above the limit
};

}  // namespace unfold
