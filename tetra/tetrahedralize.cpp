#include "tetra/tetrahedralize.h"

#include <glog/logging.h>

#include <chrono>

#include "core/errors.h"
#include "tetra/intersecting_faces.h"

namespace unfold {

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options, TetReport* report) {
  const auto start = std::chrono::steady_clock::now();
  TetReport local;
  TetReport& r = report ? *report : local;
  r = TetReport();
  // Counted on every route: a fraction of a second on 55k faces, and it says
  // why auto falls back (TetGen's conforming mode refuses any such pair).
  r.num_intersecting_faces =
      int(intersecting_face_pairs(surface.V, triangulate_faces(surface)).size());
  TetMesh tets;
  if (options.route == "conforming") {
    tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
    r.route = "conforming";
  } else if (options.route == "robust") {
    tets = tetrahedralize_robust(surface, &r);
    r.route = "robust";
  } else if (options.route == "auto") {
    try {
      tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
      r.route = "conforming";
    } catch (const NumericalError& e) {
      r.fallback = e.what();
      LOG(INFO) << "conforming tetrahedralization failed (" << e.what() << "; "
                << r.num_intersecting_faces << " intersecting face pairs); using the robust route";
      tets = tetrahedralize_robust(surface, &r);
      r.route = "robust";
    }
  } else {
    throw UsageError("unknown tetrahedralization route '" + options.route +
                     "' (known: auto, conforming, robust)");
  }
  r.num_tets = int(tets.T.rows());
  r.num_interior_points = int(tets.V.rows()) - tets.num_surface_vertices;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return tets;
}

}  // namespace unfold
