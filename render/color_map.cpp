#include "render/color_map.h"

#include <algorithm>
#include <cmath>

#include "render/draw_2d.h"

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

double color_scale_top(std::vector<double> values) {
  if (values.empty()) return 0;
  auto at = values.begin() + std::ptrdiff_t(0.98 * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

void draw_color_bar(const std::string& label, Image* image) {
  const int bar_w = 120, bar_h = 8, x0 = image->width - bar_w - 10, y0 = image->height - bar_h - 8;
  for (int x = 0; x < bar_w; ++x) {
    const Eigen::Vector3f c = color_map(double(x) / (bar_w - 1));
    fill_rect(x0 + x, y0, x0 + x + 1, y0 + bar_h,
              {std::uint8_t(c[0] * 255), std::uint8_t(c[1] * 255), std::uint8_t(c[2] * 255)},
              image);
  }
  draw_text(label, x0 - text_size(label, 1).first - 6, y0 - 1, {40, 40, 40}, 1, image);
}

}  // namespace unfold
