#include "pipeline/region_pictures.h"

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/errors.h"
#include "metrics/surface_folds.h"
#include "metrics/worst_region.h"
#include "render/color_map.h"
#include "render/write_png.h"

namespace unfold {
namespace {

// Damage is coloured on a fixed scale so that tiles compare: yellow is the
// damage bound |ln r| = ln 3 and beyond.
const double kDamageTop = std::log(kDamagedEdgeRatio);

// The close-ups of the region about `vertex` on the input and on the canonical
// form, in that order and plainly shaded, captioned "<name>: input" and `name`
// with the vertex's worst edge ratio (with `folds`, per-vertex fold degrees:
// with its fold).
std::vector<CloseUp> before_after_tiles(const Eigen::MatrixX3d& input, const Eigen::MatrixX3d& form,
                                        const Eigen::MatrixX3i& F, const SurfaceDamage& damage,
                                        int vertex, double radius_fraction, int up_axis,
                                        const std::string& name,
                                        const Eigen::VectorXd* folds = nullptr) {
  const double radius = region_radius(input, radius_fraction);
  CloseUp before = region_close_up(input, F, vertex, radius, up_axis);
  CloseUp after = region_close_up(form, F, vertex, radius / damage.scale, up_axis);
  char caption[128];
  if (folds)
    std::snprintf(caption, sizeof caption, "%s: fold %.0f deg", name.c_str(), (*folds)[vertex]);
  else
    std::snprintf(caption, sizeof caption, "%s: ratio %.3g", name.c_str(),
                  damage.per_vertex_ratio[vertex]);
  after.caption = caption;
  before.caption = name + ": input";
  return {before, after};
}

}  // namespace

CloseUp region_close_up(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int vertex,
                        double radius, int up_axis) {
  if (vertex < 0 || vertex >= V.rows())
    throw UsageError("close-up: vertex " + std::to_string(vertex) + " is not in [0, " +
                     std::to_string(V.rows()) + ")");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
    throw UsageError("close-up: a face indexes a vertex outside [0, " + std::to_string(V.rows()) +
                     ")");
  CloseUp tile;
  tile.V = V;
  tile.F = F;
  tile.centre = V.row(vertex).transpose();
  tile.radius = radius;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double area_sum = 0;  // of |normals|: against it, how much the normals cancel
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    bool inside = false;
    for (int k = 0; k < 3; ++k)
      inside |= (V.row(F(f, k)).transpose() - tile.centre).norm() <= radius;
    if (!inside) continue;
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    normal += n;
    area_sum += n.norm();
  }
  // Nearly cancelling normals point nowhere in particular: a closed part, or a
  // crumpled one (a needle's sides); the outward direction from the centroid
  // still faces the region.
  if (!(normal.norm() > 0.1 * area_sum)) normal = tile.centre - V.colwise().mean().transpose();
  if (!(normal.norm() > 0)) normal = Eigen::Vector3d::Unit((up_axis + 1) % 3);
  tile.view = view_facing(normal, up_axis);
  return tile;
}

Image render_region_before_after(const UnfoldResult& result, int vertex, double radius_fraction,
                                 int up_axis, SurfaceColoring coloring) {
  const SurfaceDamage& damage = result.metrics.damage;
  if (damage.per_vertex.size() != result.canonical.V.rows())
    throw UsageError("render_region_before_after: the result has no per-vertex damage");
  const Eigen::MatrixX3i F = triangulate_faces(result.surface);
  const bool folds = coloring == SurfaceColoring::kFolds;
  const Eigen::VectorXd values = surface_coloring_values(result, coloring);
  // 'worst' with folds: the most folded vertex (the lowest index of a tie).
  if (vertex < 0 && folds) values.maxCoeff(&vertex);
  if (vertex < 0) vertex = worst_region(damage, F).vertex;
  if (vertex >= result.surface.V.rows())
    throw UsageError("--render_focus: vertex " + std::to_string(vertex) + " is not in [0, " +
                     std::to_string(result.surface.V.rows()) + ")");
  std::vector<CloseUp> tiles =
      before_after_tiles(result.surface.V, result.canonical.V, F, damage, vertex, radius_fraction,
                         up_axis, "vertex " + std::to_string(vertex), folds ? &values : nullptr);
  CloseUpSheetOptions options;
  options.columns = 2;
  options.tile_size = 360;
  std::string title = "input | canonical";
  if (coloring != SurfaceColoring::kShading) {
    const double top =
        coloring == SurfaceColoring::kDamage ? kDamageTop
        : folds
            ? kFoldedDegrees
            : color_scale_top(std::vector<double>(values.data(), values.data() + values.size()));
    tiles[1].colors = color_map(values, 0, top);
    char legend[64];
    std::snprintf(legend, sizeof legend, "0 .. %.3g+", top);
    options.legend = legend;
    title += coloring == SurfaceColoring::kDamage ? ": edge damage"
             : folds                              ? ": folds (bend sharpened, degrees)"
                                                  : ": rigidity error";
  }
  return render_close_ups(tiles, title, options);
}

void write_worst_region_pictures(const std::string& output_dir,
                                 const std::vector<std::string>& labels,
                                 const std::vector<PoseShape>& shapes) {
  std::map<std::string, std::vector<size_t>> members;  // class -> shapes, in input order
  for (size_t i = 0; i < shapes.size(); ++i) {
    if (shapes[i].forms.size() != labels.size() || labels.empty() || !shapes[i].forms.front())
      throw UsageError("write_worst_region_pictures: shape " + shapes[i].name +
                       " needs its raw form and one entry per label");
    members[shapes[i].shape_class].push_back(i);
  }
  CloseUpSheetOptions options;
  options.tile_size = 200;
  char damage_legend[64], folds_legend[64];
  std::snprintf(damage_legend, sizeof damage_legend, "|ln r| 0 .. %.3g+ (ratio %g)", kDamageTop,
                kDamagedEdgeRatio);
  std::snprintf(folds_legend, sizeof folds_legend, "bend sharpened 0 .. %g+ degrees",
                kFoldedDegrees);
  // A gallery of a class and method: each form's tile first, its input beside it.
  const auto write_gallery = [&](const std::vector<CloseUp>& tiles, const std::string& file,
                                 const std::string& title, const char* legend) {
    if (tiles.empty()) return;
    options.legend = legend;
    write_png(file, render_close_ups(tiles, title, options));
  };
  for (const auto& [c, class_shapes] : members)
    for (size_t m = 1; m < labels.size(); ++m) {
      // Both galleries from one pass: the worst region by damage, and the most folded one.
      std::vector<CloseUp> worst, folded;
      for (size_t i : class_shapes) {
        const PoseShape& s = shapes[i];
        if (!s.forms[m]) continue;
        try {
          const Eigen::MatrixX3d &input = *s.forms.front(), &form = *s.forms[m];
          const SurfaceDamage damage = surface_damage(input, form, s.F);
          const Eigen::VectorXd folds = surface_folds(input, form, s.F).per_vertex;
          int vertex = worst_region(damage, s.F).vertex;
          std::vector<CloseUp> pair = before_after_tiles(input, form, s.F, damage, vertex,
                                                         kRegionRadiusFraction, 2, s.name);
          pair[1].colors = color_map(damage.per_vertex, 0, kDamageTop);
          worst.insert(worst.end(), {pair[1], pair[0]});
          folds.maxCoeff(&vertex);  // the lowest index of a tie
          pair = before_after_tiles(input, form, s.F, damage, vertex, kRegionRadiusFraction, 2,
                                    s.name, &folds);
          pair[1].colors = color_map(folds, 0, kFoldedDegrees);
          folded.insert(folded.end(), {pair[1], pair[0]});
        } catch (const InputError& e) {
          LOG(WARNING) << "worst region of " << s.name << ", " << labels[m] << ": " << e.what();
        } catch (const NumericalError& e) {
          LOG(WARNING) << "worst region of " << s.name << ", " << labels[m] << ": " << e.what();
        }
      }
      const std::string name = c + "_" + labels[m] + ".png";
      write_gallery(worst, output_dir + "/worst_" + name,
                    labels[m] + ": worst region of each shape | its input", damage_legend);
      write_gallery(folded, output_dir + "/folds_" + name,
                    labels[m] + ": most folded region of each shape | its input", folds_legend);
    }
}

}  // namespace unfold
