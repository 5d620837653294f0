#include "tetra/tetrahedralize.h"

#include <chrono>

#include "core/errors.h"

namespace unfold {

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options, TetReport* report) {
  const auto start = std::chrono::steady_clock::now();
  TetMesh tets;
  if (options.route == "conforming") {
    tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
  } else {
    throw UsageError("unknown tetrahedralization route '" + options.route +
                     "' (known: conforming)");
  }
  if (report) {
    report->route = options.route;
    report->num_tets = int(tets.T.rows());
    report->num_interior_points = int(tets.V.rows()) - tets.num_surface_vertices;
    report->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return tets;
}

}  // namespace unfold
