#include "render/rasterize.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/triangle_pixels.h"

namespace unfold {
namespace {

std::uint8_t to_byte(float c) { return std::uint8_t(std::lround(std::clamp(c, 0.f, 1.f) * 255)); }

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : image(width, height, background),
      depth(size_t(image.width) * size_t(image.height), std::numeric_limits<double>::infinity()) {}

void rasterize_triangle(const Eigen::Matrix3d& xyz, const Eigen::Matrix3f& colors, Canvas* canvas) {
  Image& image = canvas->image;
  for_each_covered_pixel(
      xyz.row(0).head<2>(), xyz.row(1).head<2>(), xyz.row(2).head<2>(), image.width, image.height,
      [&](int x, int y, const Eigen::Vector3d& w) {
        const double z = w[0] * xyz(0, 2) + w[1] * xyz(1, 2) + w[2] * xyz(2, 2);
        double& stored = canvas->depth[size_t(y) * size_t(image.width) + size_t(x)];
        if (!(z < stored) || z < canvas->near_depth) return;
        stored = z;
        const Eigen::Vector3f color = float(w[0]) * colors.row(0).transpose() +
                                      float(w[1]) * colors.row(1).transpose() +
                                      float(w[2]) * colors.row(2).transpose();
        image.set(x, y, {to_byte(color[0]), to_byte(color[1]), to_byte(color[2])});
      });
}

}  // namespace unfold
