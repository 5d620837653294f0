#include "stages/tetrahedralize_input.h"

#include <glog/logging.h>

#include "core/errors.h"
#include "mesh/sort_interior_vertices.h"

namespace unfold {

TetMesh surface_alone(const SurfaceMesh& surface) {
  TetMesh mesh;
  mesh.V = surface.V;
  mesh.T.resize(0, 4);
  mesh.num_surface_vertices = int(surface.V.rows());
  return mesh;
}

InputTets tetrahedralize_input(const SurfaceMesh& surface, bool open, const TetOptions& options,
                               bool fallback_surface_graph, int known_intersections) {
  InputTets out;
  std::string reason = "the surface is open";
  if (!open) {
    try {
      out.tets = tetrahedralize(surface, options, &out.report, known_intersections);
      sort_interior_vertices(&out.tets);
      LOG(INFO) << "tetrahedralized (" << out.report.route << "): " << out.tets.V.rows()
                << " vertices, " << out.tets.T.rows() << " tets in " << out.report.seconds << " s";
      return out;
    } catch (const NumericalError& e) {
      if (!fallback_surface_graph)
        throw NumericalError(std::string(e.what()) +
                             " (tetrahedralize.fallback_surface_graph: true unfolds the surface "
                             "edge graph instead)");
      reason = e.what();
    }
  }
  out.warnings.push_back("no tet mesh (" + reason + "): unfolding on the surface edge graph");
  LOG(WARNING) << out.warnings.back();
  out.report = TetReport{};
  out.report.route = "surface_graph";
  out.tets = surface_alone(surface);
  return out;
}

}  // namespace unfold
