#include "tetra/tetrahedralize.h"

#include <glog/logging.h>

#include <chrono>
#include <functional>
#include <future>
#include <optional>
#include <utility>

#include "core/errors.h"
#include "core/fork_safety.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "mesh/position_order.h"
#include "tetra/intersecting_faces.h"

namespace unfold {
namespace {

// TetGen's conforming mode refuses any pair of intersecting faces, and it
// merges vertices at equal positions, which drops a surface vertex: why it
// cannot take this surface, known before running it ("" when it may).
std::string intersections_refusal(int num_intersecting_faces) {
  if (num_intersecting_faces == 0) return "";
  return "the surface intersects itself (" + std::to_string(num_intersecting_faces) +
         " face pairs): not a valid PLC, conforming route not tried";
}

std::string duplicates_refusal(const SurfaceMesh& surface) {
  const std::vector<int> order = position_order(surface.V);
  for (size_t k = 1; k < order.size(); ++k)
    if (surface.V.row(order[k]) == surface.V.row(order[k - 1]))
      return "vertices " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) +
             " are at one position: not a valid PLC, conforming route not tried";
  return "";
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options, TetReport* report,
                       int known_intersecting_faces) {
  const auto start = std::chrono::steady_clock::now();
  TetReport local;
  TetReport& r = report ? *report : local;
  r = TetReport();
  if (options.route != "conforming" && options.route != "robust" && options.route != "auto")
    throw UsageError("unknown tetrahedralization route '" + options.route +
                     "' (known: auto, conforming, robust)");
  report_stage("tetrahedralizing " + std::to_string(surface.faces.size()) + " faces");
  // Counted on every route (unless the caller did): a fraction of a second on
  // 55k faces, and it says why auto falls back (TetGen's conforming mode
  // refuses any such pair). It runs on the other core while this one goes on:
  // from kMinParallelRows vertices with the robust route's first steps,
  // speculatively for auto (most real scans go robust; a clean surface drops
  // them); below, auto's conforming try starts at once, in TetGen's process,
  // and is stopped as soon as the count finds a pair (TetGen would only refuse
  // the surface, after seconds of work). Under ASan it is counted first
  // (core/fork_safety.h).
  const bool counted = known_intersecting_faces >= 0;
  std::shared_future<int> count;
  const auto count_faces = [&surface] {
    return int(intersecting_face_pairs(surface.V, triangulate_faces(surface)).size());
  };
  if (counted || !kForkAlongsideThreads) {
    std::promise<int> known;
    known.set_value(counted ? known_intersecting_faces : count_faces());
    count = known.get_future().share();
  } else {
    count = std::async(std::launch::async, count_faces).share();
  }
  std::optional<RobustStart> first_steps;
  if (options.route == "robust" ||
      (options.route == "auto" &&
       (counted ? known_intersecting_faces > 0 : surface.V.rows() >= kMinParallelRows)))
    first_steps = robust_start(surface, options.interior_spacing);
  const auto robust = [&] {
    if (!first_steps) first_steps = robust_start(surface, options.interior_spacing);
    r.route = "robust";
    report_stage("tetrahedralizing " + std::to_string(surface.faces.size()) +
                 " faces (robust route)");
    return tetrahedralize_robust(surface, *first_steps, &r);
  };
  TetMesh tets;
  if (options.route == "conforming") {
    r.num_intersecting_faces = count.get();
    tets = tetrahedralize_conforming(surface, options.quality, options.max_volume);
    r.route = "conforming";
  } else if (options.route == "robust") {
    tets = robust();  // the count only informs: it goes on meanwhile
    r.num_intersecting_faces = count.get();
  } else {
    // Most real scans intersect themselves: TetGen would only refuse them,
    // after seconds of work (docs/tetrahedralization.md).
    const std::string duplicates = duplicates_refusal(surface);
    const auto conforming = [&](const std::function<bool()>& give_up) {
      try {
        return std::optional<TetMesh>(
            tetrahedralize_conforming(surface, options.quality, options.max_volume, give_up));
      } catch (const NumericalError& e) {
        r.fallback = e.what();
        return std::optional<TetMesh>();
      }
    };
    std::optional<TetMesh> made;
    if (!first_steps && duplicates.empty())
      made = conforming([&count] {
        return count.wait_for(std::chrono::seconds(0)) == std::future_status::ready &&
               count.get() > 0;
      });
    r.num_intersecting_faces = count.get();
    const std::string refusal =
        r.num_intersecting_faces > 0 ? intersections_refusal(r.num_intersecting_faces) : duplicates;
    if (!refusal.empty()) {
      r.fallback = refusal;  // whatever became of the try
    } else {
      if (first_steps) made = conforming({});
      if (made) {
        tets = std::move(*made);
        r.route = "conforming";
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
