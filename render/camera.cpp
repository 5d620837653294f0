#include "render/camera.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/errors.h"

namespace unfold {
namespace {

// V in view coordinates (right, up, towards the viewer).
Eigen::MatrixX3d in_view(const Eigen::MatrixX3d& V, const View& view) {
  return V * view.axes.transpose();
}

// Pixels of view coordinates W with the view-coordinate point `center` at the panel's centre.
Eigen::MatrixX3d to_pixels(const Eigen::MatrixX3d& W, const Eigen::RowVector3d& center,
                           double scale, int width, int height) {
  Eigen::MatrixX3d pixels(W.rows(), 3);
  pixels.col(0) = (W.col(0).array() - center[0]) * scale + 0.5 * width;
  pixels.col(1) = (center[1] - W.col(1).array()) * scale + 0.5 * height;
  pixels.col(2) = -W.col(2);  // the third axis points at the viewer
  return pixels;
}

}  // namespace

int axis_index(const std::string& name, const std::string& what) {
  if (name == "x" || name == "y" || name == "z") return name[0] - 'x';
  throw UsageError(what + ": '" + name + "' is not an axis (x, y or z)");
}

std::vector<View> side_and_top_views(const Eigen::MatrixX3d& V, int up_axis) {
  if (up_axis < 0 || up_axis > 2)
    throw UsageError("render: up axis must be 0, 1 or 2 (x, y, z), not " + std::to_string(up_axis));
  const Eigen::Vector3d up = Eigen::Vector3d::Unit(up_axis);
  const Eigen::Vector3d h1 = Eigen::Vector3d::Unit((up_axis + 1) % 3),
                        h2 = Eigen::Vector3d::Unit((up_axis + 2) % 3);
  // Principal direction of the horizontal spread: the longer axis of the 2x2 covariance.
  Eigen::Vector3d length = h1;
  if (V.rows() > 1) {
    Eigen::MatrixX2d H(V.rows(), 2);
    H.col(0) = V * h1;
    H.col(1) = V * h2;
    const Eigen::MatrixX2d centered = H.rowwise() - H.colwise().mean();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(centered.transpose() * centered);
    Eigen::Vector2d d = eig.eigenvectors().col(1);
    if (d[std::abs(d[0]) >= std::abs(d[1]) ? 0 : 1] < 0) d = -d;  // a fixed sign
    length = (d[0] * h1 + d[1] * h2).normalized();
  }
  const Eigen::Vector3d width_dir = up.cross(length);
  View side{"side", Eigen::Matrix3d()}, top{"top", Eigen::Matrix3d()};
  side.axes.row(0) = length;
  side.axes.row(1) = up;
  side.axes.row(2) = length.cross(up);
  top.axes.row(0) = length;
  top.axes.row(1) = width_dir;
  top.axes.row(2) = up;
  return {side, top};
}

View view_facing(const Eigen::Vector3d& normal, int up_axis) {
  if (up_axis < 0 || up_axis > 2)
    throw UsageError("render: up axis must be 0, 1 or 2 (x, y, z), not " + std::to_string(up_axis));
  if (!normal.allFinite() || normal.norm() == 0)
    throw UsageError("view_facing: the normal must be finite and nonzero");
  const Eigen::Vector3d towards = normal.normalized();
  // Screen up: the up axis without its part along the normal; when that part
  // is nearly all of it (looking down or up), the next axis instead.
  Eigen::Vector3d up = Eigen::Vector3d::Unit(up_axis);
  if (std::abs(up.dot(towards)) > 0.95) up = Eigen::Vector3d::Unit((up_axis + 1) % 3);
  up = (up - up.dot(towards) * towards).normalized();
  View view{"facing", Eigen::Matrix3d()};
  view.axes.row(0) = up.cross(towards);
  view.axes.row(1) = up;
  view.axes.row(2) = towards;
  return view;
}

double common_scale(const std::vector<const Eigen::MatrixX3d*>& shapes, const View& view, int width,
                    int height, int margin) {
  double scale = 0;
  for (const Eigen::MatrixX3d* V : shapes) {
    if (V->rows() == 0) continue;
    const Eigen::MatrixX3d W = in_view(*V, view);
    const Eigen::Array3d extent = W.colwise().maxCoeff() - W.colwise().minCoeff();
    const double s = std::min((width - 2 * margin) / extent[0], (height - 2 * margin) / extent[1]);
    if (std::isfinite(s) && s > 0) scale = scale == 0 ? s : std::min(scale, s);
  }
  return scale > 0 ? scale : 1.0;
}

Eigen::MatrixX3d project(const Eigen::MatrixX3d& V, const View& view, double scale, int width,
                         int height) {
  return project_in_frame(V, V, view, scale, width, height);
}

Eigen::MatrixX3d project_in_frame(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V,
                                  const View& view, double scale, int width, int height) {
  const Eigen::MatrixX3d W = in_view(points, view);
  if (W.rows() == 0 || V.rows() == 0) return W;
  const Eigen::MatrixX3d frame = in_view(V, view);
  const Eigen::RowVector3d center = 0.5 * (frame.colwise().maxCoeff() + frame.colwise().minCoeff());
  return to_pixels(W, center, scale, width, height);
}

Eigen::MatrixX3d project_about(const Eigen::MatrixX3d& points, const Eigen::Vector3d& centre,
                               const View& view, double scale, int width, int height) {
  return to_pixels(in_view(points, view), (view.axes * centre).transpose(), scale, width, height);
}

}  // namespace unfold
