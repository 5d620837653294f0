#include "stages/scf_cascade.h"

#include <glog/logging.h>

#include <utility>

#include "metrics/edge_ratio.h"

namespace unfold {

ScfCascade scf_cascade(const EdgeGraph& graph, const TetMesh& tets, const SurfaceMesh& surface,
                       const ScfOptions& options) {
  ScfResult r =
      scf(graph, tets.V, tets.num_surface_vertices, triangulate_faces(surface), tets.T, options);
  ScfCascade out;
  CascadeResult& c = out.cascade;
  c.positions = std::move(r.positions);
  c.iterations = r.unbent.iterations;
  c.cascades = 1;
  c.final_energy = r.unbent.stress;
  c.edge_ratio = edge_ratio(graph, tets.V, c.positions);
  c.reached_band = true;  // no band applies
  c.history.push_back({c.iterations, 1, 0.0, c.final_energy, c.edge_ratio});
  if (const int left = r.skeleton.num_left_out) {
    out.warnings.push_back("scf: " + std::to_string(left) + " of " +
                           std::to_string(tets.num_surface_vertices) +
                           " surface vertices were not carried by the skeleton contraction (left "
                           "out by the repair); they follow their nearest vertex's node");
    LOG(WARNING) << out.warnings.back();
  }
  out.skeleton = std::move(r.skeleton);
  out.skeleton_canonical = std::move(r.canonical_nodes);
  return out;
}

}  // namespace unfold
