#include "pipeline/pose_pictures.h"

#include "core/errors.h"
#include "metrics/rigid_alignment.h"
#include "render/render_comparison.h"

namespace unfold {

Image render_poses(const std::vector<PosePanel>& panels, const Eigen::MatrixX3i& F,
                   const std::string& title) {
  if (panels.empty()) throw UsageError("render_poses: no panels");
  std::vector<RenderPanel> columns;
  Eigen::MatrixX3d reference;
  for (const PosePanel& p : panels) {
    if (!(p.scale > 0)) throw UsageError("render_poses: panel " + p.title + " has scale 0");
    if (p.V.rows() != panels.front().V.rows()) continue;
    Eigen::MatrixX3d V = p.V / p.scale;
    V.rowwise() -= V.colwise().mean();
    if (columns.empty())
      reference = V;
    else
      V = align_rigidly(reference, V).aligned;
    columns.push_back({title + ": " + p.title, V, F, {}});
  }
  RenderOptions options;
  options.panel_width = 280;
  options.panel_height = 200;
  return render_comparison(columns, options);
}

}  // namespace unfold
