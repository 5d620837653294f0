#include "pipeline/match_surfaces.h"

#include <chrono>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/progress.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

MatchShape unfold_for_matching(const SurfaceMesh& surface, const Options& options,
                               double* seconds_unfold) {
  if (options.target_vertices != 0)
    throw UsageError(
        "config key 'simplify.target_vertices' must be 0 for matching (a map covers the "
        "input's own vertices)");
  validate_match_options(options.match);
  Options unfolding = options;
  unfolding.metrics.clear();  // the matcher needs the canonical form alone
  const auto start = std::chrono::steady_clock::now();
  const UnfoldResult result = unfold_surface(surface, unfolding);
  if (seconds_unfold)
    *seconds_unfold =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return match_shape_from_canonical(result.surface, result.canonical, options);
}

MatchShape match_shape_from_canonical(const SurfaceMesh& surface, const SurfaceMesh& canonical,
                                      const Options& options) {
  if (surface.V.rows() != canonical.V.rows())
    throw UsageError("a canonical form of " + std::to_string(canonical.V.rows()) +
                     " vertices for a surface of " + std::to_string(surface.V.rows()));
  report_stage("spectral basis of " + std::to_string(surface.V.rows()) + " vertices");
  return prepare_match_shape(surface.V, canonical.V, triangulate_faces(surface), options.match);
}

ShapeMatch match_surfaces(const SurfaceMesh& source, const SurfaceMesh& target,
                          const Options& options) {
  const MatchShape a = unfold_for_matching(source, options);
  const MatchShape b = unfold_for_matching(target, options);
  report_stage("matching");
  return match_shapes(a, b, options.match);
}

void write_map(const std::string& path, const Eigen::VectorXi& map) {
  write_file_atomically(path, [&](std::ostream& out) {
    for (Eigen::Index i = 0; i < map.size(); ++i) out << map(i) << '\n';
  });
}

}  // namespace unfold
