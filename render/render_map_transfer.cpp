#include "render/render_map_transfer.h"

#include <string>
#include <vector>

#include "core/errors.h"
#include "geometry/point_tree.h"
#include "render/render_comparison.h"

namespace unfold {

Eigen::MatrixX3f position_colors(const Eigen::MatrixX3d& V) {
  if (V.rows() == 0) return Eigen::MatrixX3f(0, 3);
  const Eigen::RowVector3d low = V.colwise().minCoeff();
  const Eigen::RowVector3d extent =
      (V.colwise().maxCoeff() - low).cwiseMax(Eigen::RowVector3d::Constant(1e-300));
  const Eigen::MatrixX3d unit = (V.rowwise() - low).array().rowwise() / extent.array();
  // Kept off black and white so the shading still reads.
  return (0.1 + 0.8 * unit.array()).cast<float>().matrix();
}

Eigen::MatrixX3f transfer_colors(const Eigen::MatrixX3f& source_colors, const Eigen::VectorXi& map,
                                 const Eigen::MatrixX3d& target_V) {
  if (source_colors.rows() != map.size())
    throw UsageError("transfer_colors: " + std::to_string(map.size()) + " map entries for " +
                     std::to_string(source_colors.rows()) + " source colours");
  const Eigen::Index n = target_V.rows();
  if (map.size() > 0 && (map.minCoeff() < 0 || map.maxCoeff() >= n))
    throw UsageError("transfer_colors: the map names a vertex outside the target");
  Eigen::MatrixX3f colors = Eigen::MatrixX3f::Zero(n, 3);
  Eigen::VectorXi hits = Eigen::VectorXi::Zero(n);
  for (Eigen::Index i = 0; i < map.size(); ++i) {
    colors.row(map(i)) += source_colors.row(i);
    ++hits(map(i));
  }
  std::vector<int> hit;
  for (Eigen::Index j = 0; j < n; ++j)
    if (hits(j) > 0) {
      colors.row(j) /= float(hits(j));
      hit.push_back(int(j));
    }
  if (hit.empty()) return colors;
  Eigen::MatrixX3d hit_points(Eigen::Index(hit.size()), 3);
  for (size_t k = 0; k < hit.size(); ++k) hit_points.row(Eigen::Index(k)) = target_V.row(hit[k]);
  const PointTree tree(hit_points);
  for (Eigen::Index j = 0; j < n; ++j)
    if (hits(j) == 0) colors.row(j) = colors.row(hit[tree.nearest(target_V.row(j).transpose())]);
  return colors;
}

Image render_map_transfer(const SurfaceMesh& source, const SurfaceMesh& target,
                          const Eigen::VectorXi& map, int up_axis) {
  const Eigen::MatrixX3f colors = position_colors(source.V);
  std::vector<RenderPanel> panels(2);
  panels[0].title = "source";
  panels[0].V = source.V;
  panels[0].F = triangulate_faces(source);
  panels[0].colors = colors;
  panels[1].title = "target, through the map";
  panels[1].V = target.V;
  panels[1].F = triangulate_faces(target);
  panels[1].colors = transfer_colors(colors, map, target.V);
  RenderOptions options;
  options.up_axis = up_axis;
  return render_comparison(panels, options);
}

}  // namespace unfold
