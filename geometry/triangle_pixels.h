// The pixels a triangle covers: those whose centres (x + 0.5, y + 0.5) lie
// inside it, for either winding, with their barycentric weights. The
// renderer's rasterisation and the retrieval's silhouette area share it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace unfold {

/// Calls visit(x, y, w) for every pixel (x, y) of a width x height grid whose
/// centre lies inside the triangle abc, with w its barycentric weights at the
/// centre (each >= 0, summing to 1). Pixel coordinates: pixel (x, y) spans
/// [x, x + 1) x [y, y + 1). A degenerate (zero-area) or non-finite triangle
/// covers nothing.
template <class Visit>
void for_each_covered_pixel(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                            const Eigen::Vector2d& c, int width, int height, Visit&& visit) {
  const auto edge = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, double x, double y) {
    return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
  };
  const double area = edge(a, b, c.x(), c.y());
  if (area == 0 || !std::isfinite(area)) return;
  const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
  const int x1 = std::min(width - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
  const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
  const int y1 = std::min(height - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      // Signed by the winding, so divided by the area: inside is all >= 0 either way.
      const Eigen::Vector3d w(edge(b, c, px, py) / area, edge(c, a, px, py) / area,
                              edge(a, b, px, py) / area);
      if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0) visit(x, y, w);
    }
}

}  // namespace unfold
