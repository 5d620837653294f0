#include "metrics/silhouette_area.h"

#include <algorithm>
#include <vector>

#include "core/errors.h"
#include "geometry/triangle_pixels.h"

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
  std::vector<char> covered(size_t(resolution) * size_t(resolution), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for_each_covered_pixel(pixel(F(f, 0)), pixel(F(f, 1)), pixel(F(f, 2)), resolution, resolution,
                           [&](int x, int y, const Eigen::Vector3d&) {
                             covered[size_t(y) * size_t(resolution) + size_t(x)] = 1;
                           });
  return long(std::count(covered.begin(), covered.end(), 1));
}

}  // namespace unfold
