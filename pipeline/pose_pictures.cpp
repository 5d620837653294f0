#include "pipeline/pose_pictures.h"

#include "core/errors.h"
#include "metrics/pose_invariance.h"
#include "metrics/rigid_alignment.h"
#include "render/render_comparison.h"

namespace unfold {

Image render_poses(const std::vector<PosePanel>& panels, const std::string& title) {
  if (panels.empty()) throw UsageError("render_poses: no panels");
  std::vector<RenderPanel> columns;
  Eigen::MatrixX3d reference;  // the first panel's corresponding points
  for (const PosePanel& p : panels) {
    Eigen::MatrixX3d V = scaled_to_unit_area(p.V, p.F);
    if (p.rows.size() > 0 && (p.rows.minCoeff() < 0 || p.rows.maxCoeff() >= V.rows()))
      throw UsageError("render_poses: panel " + p.title + " names a vertex out of range");
    const Eigen::MatrixX3d points = p.rows.size() > 0 ? Eigen::MatrixX3d(V(p.rows, Eigen::all)) : V;
    if (columns.empty()) {
      const Eigen::RowVector3d centre = points.colwise().mean();
      V.rowwise() -= centre;
      reference = points.rowwise() - centre;
    } else {
      if (points.rows() != reference.rows())
        throw UsageError("render_poses: panel " + p.title +
                         " has another number of corresponding points than the first");
      const RigidAlignment a = align_rigidly(reference, points);
      V = ((V * a.R.transpose()).rowwise() + a.t.transpose()).eval();
    }
    columns.push_back({title + ": " + p.title, V, p.F, {}});
  }
  RenderOptions options;
  options.panel_width = 280;
  options.panel_height = 200;
  return render_comparison(columns, options);
}

}  // namespace unfold
