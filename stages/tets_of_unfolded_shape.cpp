#include "stages/tets_of_unfolded_shape.h"

#include <glog/logging.h>

#include <utility>

#include "solvers/tetrahedralize_unfolded.h"

namespace unfold {

UnfoldedShapeTets tets_of_unfolded_shape(const SurfaceMesh& surface, const Eigen::MatrixX3d& S,
                                         TetOptions tet, bool surface_edges_join) {
  if (tet.route == "auto") tet.route = "robust";
  UnfoldedTetMesh unfolded = tetrahedralize_unfolded(surface, S, tet, surface_edges_join);
  UnfoldedShapeTets out;
  out.rest = std::move(unfolded.rest);
  out.report = unfolded.report;
  out.positions = unfolded.unfolded.rowwise() - unfolded.unfolded.colwise().mean();
  out.unfolded = std::move(unfolded.unfolded);
  LOG(INFO) << "tetrahedralized the unfolded shape (" << out.report.route
            << "): " << out.rest.V.rows() << " vertices, " << out.rest.T.rows() << " tets; "
            << out.report.dropped_inverted_tets << " inverted and " << out.report.dropped_flat_tets
            << " flat at rest dropped, " << out.report.inverted_rest_tets
            << " kept to keep it connected";
  return out;
}

}  // namespace unfold
