// Dense correspondence between two surfaces through their canonical forms
// (issue 46): each surface unfolded (unfold_surface), then matched
// (solvers/match_canonical_forms.h). What unfold_match and the Python module's
// correspond() call.
#pragma once

#include <string>

#include "config/options.h"
#include "mesh/surface_mesh.h"
#include "solvers/match_canonical_forms.h"

namespace unfold {

/// The matcher's view of one input surface: unfolded with `options` (metrics
/// off: the matcher needs the canonical form alone), triangulated, its
/// spectral basis computed (match.refine zoomout).
/// @param seconds_unfold if given, set to the unfolding's wall time
/// @throws UsageError if options.target_vertices is not 0 (a map must cover
///         the input's own vertices); as unfold_surface and prepare_match_shape
MatchShape unfold_for_matching(const SurfaceMesh& surface, const Options& options,
                               double* seconds_unfold = nullptr);

/// The same from a canonical form computed before (e.g. read back from a
/// cache): only the spectral basis is computed.
/// @throws UsageError if the two meshes' vertex counts differ
MatchShape match_shape_from_canonical(const SurfaceMesh& surface, const SurfaceMesh& canonical,
                                      const Options& options);

/// Maps every vertex of `source` to a vertex of `target` (result.map, 0-based).
/// @throws as unfold_for_matching and match_shapes
ShapeMatch match_surfaces(const SurfaceMesh& source, const SurfaceMesh& target,
                          const Options& options);

/// The map file: one line per source vertex, its 0-based target vertex id.
/// Written atomically (no partial file on failure).
/// @throws OutputError naming the path
void write_map(const std::string& path, const Eigen::VectorXi& map);

}  // namespace unfold
