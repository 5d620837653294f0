#include "pipeline/scf_unfold.h"

#include <glog/logging.h>

#include <string>
#include <utility>

#include "metrics/edge_ratio.h"
#include "solvers/scf.h"

namespace unfold {

void unfold_scf(const EdgeGraph& graph, const ScfOptions& options, UnfoldResult* result) {
  const TetMesh& tets = result->tets;
  ScfResult r = scf(graph, tets.V, tets.num_surface_vertices, triangulate_faces(result->surface),
                    tets.T, options);
  CascadeResult& c = result->cascade;
  c.positions = std::move(r.positions);
  c.iterations = r.unbent.iterations;
  c.cascades = 1;
  c.final_energy = r.unbent.stress;
  c.edge_ratio = edge_ratio(graph, tets.V, c.positions);
  c.reached_band = true;  // no band applies
  c.history.push_back({c.iterations, 1, 0.0, c.final_energy, c.edge_ratio});
  if (const int left = r.skeleton.num_left_out) {
    result->warnings.push_back(
        "scf: " + std::to_string(left) + " of " + std::to_string(tets.num_surface_vertices) +
        " surface vertices were not carried by the skeleton contraction (left "
        "out by the repair); they follow their nearest vertex's node");
    LOG(WARNING) << result->warnings.back();
  }
  result->skeleton = std::move(r.skeleton);
  result->skeleton_canonical = std::move(r.canonical_nodes);
}

}  // namespace unfold
