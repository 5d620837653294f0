#include "solvers/scf.h"

#include <glog/logging.h>

#include <cmath>
#include <utility>

#include "core/errors.h"
#include "solvers/skeleton_deformation.h"

namespace unfold {

void validate_scf_options(const ScfOptions& o) {
  validate_curve_skeleton_options(o.skeleton);
  if (o.mds_iterations < 1) throw UsageError("config key 'scf.mds_iterations' must be >= 1");
  if (!(std::isfinite(o.blend_radius) && o.blend_radius > 0))
    throw UsageError("config key 'scf.blend_radius' must be a positive finite number");
  if (!(std::isfinite(o.arap_anchor) && o.arap_anchor > 0))
    throw UsageError("config key 'scf.arap_anchor' must be a positive finite number");
  if (o.arap_iterations < 0) throw UsageError("config key 'scf.arap_iterations' must be >= 0");
}

ScfResult scf(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int num_surface_vertices,
              const Eigen::MatrixX3i& F, const ScfOptions& options) {
  validate_scf_options(options);
  if (P.rows() != graph.num_vertices || num_surface_vertices < 1 || num_surface_vertices > P.rows())
    throw UsageError("scf: positions, edge graph and surface vertex count do not match");
  const Eigen::MatrixX3d surface = P.topRows(num_surface_vertices);
  ScfResult r;
  r.skeleton = curve_skeleton(surface, F, options.skeleton);
  r.unbent = unbend_skeleton(r.skeleton.nodes, r.skeleton.edges, options.mds_iterations);
  SkeletonDeformationOptions deform;
  deform.blend_radius = options.blend_radius * 2 *
                        (surface.rowwise() - surface.colwise().mean()).rowwise().norm().maxCoeff();
  deform.arap_anchor = options.arap_anchor;
  deform.arap_iterations = options.arap_iterations;
  SkeletonDeformation d = deform_by_skeleton(graph, P, r.skeleton, r.unbent, deform);
  r.positions = std::move(d.positions);
  r.skinned = std::move(d.skinned);
  r.canonical_nodes = std::move(d.canonical_nodes);
  LOG(INFO) << "scf: " << r.skeleton.nodes.rows() << " skeleton nodes, skeleton MDS stress "
            << r.unbent.stress << " after " << r.unbent.iterations << " transforms";
  return r;
}

}  // namespace unfold
