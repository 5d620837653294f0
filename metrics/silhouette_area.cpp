#include "metrics/silhouette_area.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.h"

namespace unfold {

long silhouette_pixels(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int axis,
                       int resolution) {
  if (axis < 0 || axis > 2) throw UsageError("silhouette: the axis must be 0, 1 or 2");
  if (resolution < 1) throw UsageError("silhouette: the resolution must be at least 1 pixel");
  const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
  // Pixel coordinates: [-1, 1] onto [0, resolution], pixel (x, y) centred at (x + 0.5, y + 0.5).
  const double scale = resolution / 2.0;
  const auto pixel = [&](int vertex) {
    return Eigen::Vector2d((V(vertex, u) + 1) * scale, (V(vertex, v) + 1) * scale);
  };
  const auto edge = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, double x, double y) {
    return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
  };
  std::vector<char> covered(size_t(resolution) * size_t(resolution), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector2d a = pixel(F(f, 0)), b = pixel(F(f, 1)), c = pixel(F(f, 2));
    const double area = edge(a, b, c.x(), c.y());
    if (area == 0 || !std::isfinite(area)) continue;
    const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(resolution - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(resolution - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Signed by the winding, so divided by the area: inside is all >= 0 either way.
        if (edge(b, c, px, py) / area >= 0 && edge(c, a, px, py) / area >= 0 &&
            edge(a, b, px, py) / area >= 0)
          covered[size_t(y) * size_t(resolution) + size_t(x)] = 1;
      }
  }
  return long(std::count(covered.begin(), covered.end(), 1));
}

}  // namespace unfold
