#include "pipeline/result_pictures.h"

#include <cstdio>

#include "core/errors.h"
#include "metrics/surface_folds.h"
#include "render/color_map.h"

namespace unfold {

SurfaceColoring surface_coloring(const std::string& name) {
  if (name == "shading") return SurfaceColoring::kShading;
  if (name == "rigidity") return SurfaceColoring::kRigidity;
  if (name == "damage") return SurfaceColoring::kDamage;
  if (name == "folds") return SurfaceColoring::kFolds;
  throw UsageError("'" + name + "' is not shading, rigidity, damage or folds");
}

Eigen::VectorXd surface_coloring_values(const UnfoldResult& result, SurfaceColoring coloring) {
  if (coloring == SurfaceColoring::kRigidity)
    return result.metrics.rigidity_per_vertex.head(result.canonical.V.rows());
  if (coloring == SurfaceColoring::kDamage) {
    if (result.metrics.damage.per_vertex.size() != result.canonical.V.rows())
      throw UsageError("render_before_after: the result has no per-vertex damage");
    return result.metrics.damage.per_vertex;
  }
  if (coloring == SurfaceColoring::kFolds) {
    if (result.metrics.folds.per_vertex.size() != result.canonical.V.rows())
      throw UsageError("render_before_after: the result has no per-vertex folds");
    return result.metrics.folds.per_vertex;
  }
  return {};
}

Image render_before_after(const UnfoldResult& result, const RenderOptions& options,
                          SurfaceColoring coloring, bool draw_skeleton) {
  const Eigen::MatrixX3i F = triangulate_faces(result.surface);
  RenderPanel before{"input", result.surface.V, F, {}};
  RenderPanel after{"canonical", result.canonical.V, F, {}};
  after.values = surface_coloring_values(result, coloring);
  if (coloring == SurfaceColoring::kFolds) {
    // A fixed scale, as damage's in close-ups: yellow is folded, whatever the shape.
    after.colors = color_map(after.values, 0, kFoldedDegrees);
    after.values.resize(0);
  }
  if (coloring == SurfaceColoring::kRigidity) after.title = "canonical: rigidity error";
  if (coloring == SurfaceColoring::kDamage) after.title = "canonical: edge damage";
  if (coloring == SurfaceColoring::kFolds) after.title = "canonical: folds";
  if (draw_skeleton) {
    const CurveSkeleton& s = result.skeleton;
    if (s.edges.rows() == 0 || result.skeleton_canonical.rows() != s.nodes.rows())
      throw UsageError("render_before_after: the result has no skeleton (method scf draws one)");
    before.line_points = s.nodes;
    after.line_points = result.skeleton_canonical;
    before.lines = after.lines = s.edges;
  }
  return render_comparison({before, after}, options);
}

Image render_beta_sweep(const std::vector<UnfoldResult>& runs, const std::vector<double>& betas,
                        const RenderOptions& options) {
  if (runs.size() != betas.size() || runs.empty())
    throw UsageError("render_beta_sweep: " + std::to_string(runs.size()) + " runs for " +
                     std::to_string(betas.size()) + " betas");
  const Eigen::MatrixX3i F = triangulate_faces(runs.front().surface);
  std::vector<RenderPanel> panels = {{"input", runs.front().surface.V, F, {}}};
  for (size_t k = 0; k < runs.size(); ++k) {
    char title[64];
    std::snprintf(title, sizeof title, "beta %g n/l2", betas[k]);
    panels.push_back({title, runs[k].canonical.V, F, {}});
  }
  return render_comparison(panels, options);
}

}  // namespace unfold
