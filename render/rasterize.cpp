#include "render/rasterize.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace unfold {
namespace {

std::uint8_t to_byte(float c) { return std::uint8_t(std::lround(std::clamp(c, 0.f, 1.f) * 255)); }

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : image(width, height, background),
      depth(size_t(image.width) * size_t(image.height), std::numeric_limits<double>::infinity()) {}

void rasterize_triangle(const Eigen::Matrix3d& xyz, const Eigen::Matrix3f& colors, Canvas* canvas) {
  const Eigen::Vector2d a = xyz.row(0).head<2>(), b = xyz.row(1).head<2>(),
                        c = xyz.row(2).head<2>();
  const auto edge = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, double x, double y) {
    return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
  };
  const double area = edge(a, b, c.x(), c.y());
  if (area == 0 || !std::isfinite(area)) return;
  Image& image = canvas->image;
  const int x0 = std::max(0, int(std::floor(xyz.col(0).minCoeff())));
  const int x1 = std::min(image.width - 1, int(std::ceil(xyz.col(0).maxCoeff())));
  const int y0 = std::max(0, int(std::floor(xyz.col(1).minCoeff())));
  const int y1 = std::min(image.height - 1, int(std::ceil(xyz.col(1).maxCoeff())));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      // Barycentric weights, positive inside for either winding.
      const double w0 = edge(b, c, px, py) / area, w1 = edge(c, a, px, py) / area,
                   w2 = edge(a, b, px, py) / area;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double z = w0 * xyz(0, 2) + w1 * xyz(1, 2) + w2 * xyz(2, 2);
      double& stored = canvas->depth[size_t(y) * size_t(image.width) + size_t(x)];
      if (!(z < stored)) continue;
      stored = z;
      const Eigen::Vector3f color = float(w0) * colors.row(0).transpose() +
                                    float(w1) * colors.row(1).transpose() +
                                    float(w2) * colors.row(2).transpose();
      image.set(x, y, {to_byte(color[0]), to_byte(color[1]), to_byte(color[2])});
    }
}

}  // namespace unfold
