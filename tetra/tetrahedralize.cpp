#include "tetra/tetrahedralize.h"

#include <glog/logging.h>

#include <chrono>
#include <future>
#include <optional>

#include "core/errors.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "mesh/position_order.h"
#include "tetra/intersecting_faces.h"

namespace unfold {
namespace {

// Why TetGen's conforming mode cannot take this surface, known before running
// it ("" when it may): it refuses any pair of intersecting faces, and it
// merges vertices at equal positions, which drops a surface vertex.
std::string not_a_plc(const SurfaceMesh& surface, int num_intersecting_faces) {
  if (num_intersecting_faces > 0)
    return "the surface intersects itself (" + std::to_string(num_intersecting_faces) +
           " face pairs): not a valid PLC, conforming route not tried";
  const std::vector<int> order = position_order(surface.V);
  for (size_t k = 1; k < order.size(); ++k)
    if (surface.V.row(order[k]) == surface.V.row(order[k - 1]))
      return "vertices " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) +
             " are at one position: not a valid PLC, conforming route not tried";
  return "";
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options, TetReport* report) {
  const auto start = std::chrono::steady_clock::now();
  TetReport local;
  TetReport& r = report ? *report : local;
  r = TetReport();
  if (options.route != "conforming" && options.route != "robust" && options.route != "auto")
    throw UsageError("unknown tetrahedralization route '" + options.route +
                     "' (known: auto, conforming, robust)");
  report_stage("tetrahedralizing " + std::to_string(surface.faces.size()) + " faces");
  // Counted on every route: a fraction of a second on 55k faces, and it says
  // why auto falls back (TetGen's conforming mode refuses any such pair). From
  // kMinParallelRows vertices the robust route's first steps are taken on the
  // other core meanwhile, speculatively for auto (most real scans go robust; a
  // clean surface drops them).
  auto count = std::async(std::launch::async, [&surface] {
    return int(intersecting_face_pairs(surface.V, triangulate_faces(surface)).size());
  });
  std::optional<RobustStart> first_steps;
  if (options.route == "robust" ||
      (options.route == "auto" && surface.V.rows() >= kMinParallelRows))
    first_steps = robust_start(surface);
  r.num_intersecting_faces = count.get();
  const auto robust = [&] {
    if (!first_steps) first_steps = robust_start(surface);
    r.route = "robust";
    report_stage("tetrahedralizing " + std::to_string(surface.faces.size()) +
                 " faces (robust route)");
    return tetrahedralize_robust(surface, *first_steps, &r);
  };
  TetMesh tets;
  if (options.route == "conforming") {
    tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
    r.route = "conforming";
  } else if (options.route == "robust") {
    tets = robust();
  } else {
    // Most real scans intersect themselves: TetGen would only refuse them,
    // after seconds of work (docs/tetrahedralization.md).
    r.fallback = not_a_plc(surface, r.num_intersecting_faces);
    if (r.fallback.empty()) {
      try {
        tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
        r.route = "conforming";
      } catch (const NumericalError& e) {
        r.fallback = e.what();
      }
    }
    if (r.route.empty()) {
      LOG(INFO) << "no conforming tetrahedralization (" << r.fallback
                << "); using the robust route";
      tets = robust();
    }
  }
  r.num_tets = int(tets.T.rows());
  r.num_interior_points = int(tets.V.rows()) - tets.num_surface_vertices;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return tets;
}

}  // namespace unfold
