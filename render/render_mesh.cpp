#include "render/render_mesh.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.h"

namespace unfold {
namespace {

// Two-sided headlight: the light comes from the viewer, so brightness is |n . view|.
float lambert(const Eigen::Vector3d& normal, const View& view) {
  const double norm = normal.norm();
  if (norm == 0) return 0.35f;
  return float(0.35 + 0.65 * std::abs(normal.dot(view.axes.row(2).transpose())) / norm);
}

// Draws the triangles F of V with their corners at `pixels` (a row per vertex of V:
// project()'s or project_about()'s).
void render_projected(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                      const Eigen::MatrixX3f& colors, const View& view,
                      const Eigen::MatrixX3d& pixels, Shading shading, Canvas* canvas) {
  if (colors.rows() != 0 && colors.rows() != V.rows())
    throw UsageError("render_mesh: " + std::to_string(colors.rows()) + " colours for " +
                     std::to_string(V.rows()) + " vertices");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
    throw UsageError("render_mesh: a face indexes a vertex outside [0, " +
                     std::to_string(V.rows()) + ")");
  const Eigen::Vector3f neutral(0.85f, 0.78f, 0.66f);
  const auto base = [&](int v) -> Eigen::Vector3f {
    return colors.rows() ? Eigen::Vector3f(colors.row(v).transpose()) : neutral;
  };
  // Area-weighted vertex normals for Gouraud shading.
  Eigen::MatrixX3d face_normals(F.rows(), 3), vertex_normals = Eigen::MatrixX3d::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    face_normals.row(f) = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) vertex_normals.row(F(f, k)) += face_normals.row(f);
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    Eigen::Matrix3d xyz;
    Eigen::Matrix3f rgb;
    const Eigen::Vector3f flat =
        (base(F(f, 0)) + base(F(f, 1)) + base(F(f, 2))) / 3 * lambert(face_normals.row(f), view);
    for (int k = 0; k < 3; ++k) {
      xyz.row(k) = pixels.row(F(f, k));
      const Eigen::Vector3f c =
          shading == Shading::kGouraud
              ? Eigen::Vector3f(lambert(vertex_normals.row(F(f, k)), view) * base(F(f, k)))
              : flat;
      rgb.row(k) = c.transpose();
    }
    rasterize_triangle(xyz, rgb, canvas);
  }
}

}  // namespace

void render_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                 const Eigen::MatrixX3f& colors, const View& view, double scale, Shading shading,
                 Canvas* canvas) {
  render_projected(V, F, colors, view,
                   project(V, view, scale, canvas->image.width, canvas->image.height), shading,
                   canvas);
}

void render_mesh_about(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                       const Eigen::MatrixX3f& colors, const View& view,
                       const Eigen::Vector3d& centre, double scale, Shading shading,
                       Canvas* canvas) {
  render_projected(V, F, colors, view,
                   project_about(V, centre, view, scale, canvas->image.width, canvas->image.height),
                   shading, canvas);
}

}  // namespace unfold
