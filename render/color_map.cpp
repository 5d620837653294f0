#include "render/color_map.h"

#include <algorithm>
#include <cmath>

namespace unfold {

Eigen::Vector3f color_map(double t) {
  if (std::isnan(t)) return {0.5f, 0.5f, 0.5f};
  // Five samples of matplotlib's viridis, interpolated linearly.
  static const float stops[5][3] = {{0.267f, 0.005f, 0.329f},
                                    {0.231f, 0.322f, 0.545f},
                                    {0.129f, 0.569f, 0.549f},
                                    {0.369f, 0.788f, 0.384f},
                                    {0.993f, 0.906f, 0.144f}};
  const double s = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(int(s), 3);
  const float f = float(s - i);
  Eigen::Vector3f c;
  for (int k = 0; k < 3; ++k) c[k] = stops[i][k] * (1 - f) + stops[i + 1][k] * f;
  return c;
}

Eigen::MatrixX3f color_map(const Eigen::VectorXd& values, double low, double high) {
  Eigen::MatrixX3f colors(values.size(), 3);
  const double range = high - low;
  for (Eigen::Index i = 0; i < values.size(); ++i)
    colors.row(i) = color_map(range > 0 ? (values[i] - low) / range : 0.0).transpose();
  return colors;
}

}  // namespace unfold
