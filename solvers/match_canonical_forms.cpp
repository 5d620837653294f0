#include "solvers/match_canonical_forms.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/errors.h"
#include "core/seconds_since.h"
#include "geometry/point_tree.h"

namespace unfold {
void validate_match_options(const MatchOptions& o) {
  if (o.mirror != "auto" && o.mirror != "off")
    throw UsageError("config key 'match.mirror' must be auto or off, got '" + o.mirror + "'");
  if (!(o.mirror_margin >= 0 && o.mirror_margin < 1))
    throw UsageError("config key 'match.mirror_margin' must be in [0, 1)");
  if (o.refine != "zoomout" && o.refine != "none")
    throw UsageError("config key 'match.refine' must be zoomout or none, got '" + o.refine + "'");
  if (o.spectral_size < o.zoomout.start_size || o.spectral_size > 500)
    throw UsageError("config key 'match.spectral_size' must be in [" +
                     std::to_string(o.zoomout.start_size) + ", 500]");
}

MatchShape prepare_match_shape(const Eigen::MatrixX3d& V, const Eigen::MatrixX3d& canonical,
                               const Eigen::MatrixX3i& F, const MatchOptions& options) {
  validate_match_options(options);
  if (V.rows() != canonical.rows())
    throw UsageError("prepare_match_shape: the canonical form has " +
                     std::to_string(canonical.rows()) + " vertices, the surface " +
                     std::to_string(V.rows()));
  MatchShape shape{V, canonical, F, {}, 0};
  if (options.refine == "zoomout") {
    const auto start = std::chrono::steady_clock::now();
    if (options.spectral_size >= V.rows())
      throw InputError("a shape of " + std::to_string(V.rows()) +
                       " vertices is too small for match.spectral_size " +
                       std::to_string(options.spectral_size));
    shape.basis = laplace_beltrami_basis(V, F, options.spectral_size);
    shape.seconds_basis = seconds_since(start);
  }
  return shape;
}

ShapeMatch match_shapes(const MatchShape& source, const MatchShape& target,
                        const MatchOptions& options, const Eigen::Matrix3d* rotation_seed,
                        FormAlignments aligned) {
  validate_match_options(options);
  ShapeMatch result;
  auto start = std::chrono::steady_clock::now();
  if (aligned.candidates.empty()) {
    aligned = align_canonical_forms(source.canonical, source.F, target.canonical, target.F,
                                    options.alignment, rotation_seed);
  } else if (rotation_seed) {
    add_seeded_alignment(*rotation_seed, options.alignment, &aligned);
  }
  const FormAlignments& a = aligned;
  const PointTree tree(a.target);
  const FormAlignment* best_fit = nullptr;
  // rotation, mirrored: the best fits; the seeded rotation instead when there is one
  const FormAlignment* chosen[2] = {nullptr, nullptr};
  for (const FormAlignment& c : a.candidates) {
    const int side = c.mirrored;
    const bool better =
        !chosen[side] || (c.seeded ? !chosen[side]->seeded
                                   : !chosen[side]->seeded && c.residual < chosen[side]->residual);
    if (better) chosen[side] = &c;
    if (!c.seeded && (!best_fit || c.residual < best_fit->residual)) best_fit = &c;
  }
  result.from_collection = chosen[0]->seeded;
  Eigen::VectorXi chosen_map[2] = {tree.nearest_rows(chosen[0]->moved),
                                   tree.nearest_rows(chosen[1]->moved)};
  result.rigid = best_fit == chosen[best_fit->mirrored] ? chosen_map[best_fit->mirrored]
                                                        : tree.nearest_rows(best_fit->moved);
  result.candidates = int(a.candidates.size());
  result.rotation_residual = chosen[0]->residual;
  result.mirrored_residual = chosen[1]->residual;
  const double ratio = chosen[1]->residual / chosen[0]->residual;
  char text[200];
  if (options.mirror == "off") {
    result.mirrored = best_fit->mirrored;
    std::snprintf(text, sizeof text,
                  "%s (the better fit; the mirror image fits %.2fx the rotation)",
                  result.mirrored ? "mirrored" : "rotation", ratio);
    result.oriented = result.rigid;
  } else {
    // A rigid motion cannot mirror a shape: the rotation's map unless the
    // mirror image fits clearly better (the two forms' asymmetry decides).
    result.mirrored = ratio < 1 - options.mirror_margin;
    result.ambiguous = !result.mirrored && ratio < 1 / (1 - options.mirror_margin);
    std::snprintf(text, sizeof text,
                  result.mirrored    ? "mirrored (the mirror image fits %.2fx the rotation%s)"
                  : result.ambiguous ? "ambiguous: kept the rotation (the mirror image fits %.2fx "
                                       "the rotation%s, within the margin)"
                                     : "rotation (the mirror image fits %.2fx the rotation%s)",
                  ratio, result.from_collection ? " placed by the collection" : "");
    result.oriented = chosen_map[result.mirrored];
  }
  result.decision = text;
  result.seconds_align = seconds_since(start);

  result.map = result.oriented;
  if (options.refine == "zoomout") {
    if (source.basis.phi.cols() < options.spectral_size ||
        target.basis.phi.cols() < options.spectral_size)
      throw UsageError("match_shapes: a shape was prepared without its spectral basis");
    start = std::chrono::steady_clock::now();
    ZoomOutOptions zoom = options.zoomout;
    zoom.final_size = options.spectral_size;
    result.map = zoomout(source.basis, target.basis, result.oriented, zoom);
    result.seconds_refine = seconds_since(start);
  }
  return result;
}

}  // namespace unfold
