#include "render/depth_image.h"

#include <Eigen/Geometry>

#include "core/errors.h"
#include "render/rasterize.h"

namespace unfold {

GrayImage depth_image(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                      const Eigen::Vector3d& direction, int size) {
  if (size < 8) throw UsageError("depth image: size must be at least 8 pixels");
  const Eigen::Vector3d toward = -direction;  // from the camera into the scene
  Eigen::Index least;
  toward.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d up = (Eigen::Vector3d::Unit(least) - toward * toward[least]).normalized();
  const Eigen::Vector3d right = up.cross(toward);
  // Pixel x right, y down; depth from the plane one unit in front of the origin.
  Eigen::MatrixX3d screen(V.rows(), 3);
  screen.col(0) = (V * right).array() * (size / 2.0) + size / 2.0;
  screen.col(1) = (V * up).array() * (-size / 2.0) + size / 2.0;
  screen.col(2) = (V * toward).array() + 1.0;
  Canvas canvas(size, size, {0, 0, 0});
  Eigen::Matrix3d xyz;
  Eigen::Matrix3f grey;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      xyz.row(k) = screen.row(F(f, k));
      grey.row(k).setConstant(float(1 - xyz(k, 2) / 2));
    }
    rasterize_triangle(xyz, grey, &canvas);
  }
  GrayImage image{size, std::vector<std::uint8_t>(size_t(size) * size_t(size))};
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = canvas.image.pixels[3 * i];
  return image;
}

}  // namespace unfold
