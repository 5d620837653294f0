#include "solvers/match_canonical_forms.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/seconds_since.h"
#include "geometry/point_tree.h"
#include "mesh/lumped_masses.h"
#include "mesh/mean_curvature_scales.h"
#include "metrics/descriptor_disagreement.h"

namespace unfold {
void validate_match_options(const MatchOptions& o) {
  if (o.mirror != "auto" && o.mirror != "off")
    throw UsageError("config key 'match.mirror' must be auto or off, got '" + o.mirror + "'");
  if (!(o.mirror_margin >= 0 && o.mirror_margin < 1))
    throw UsageError("config key 'match.mirror_margin' must be in [0, 1)");
  if (o.placement != "descriptor" && o.placement != "residual")
    throw UsageError("config key 'match.placement' must be descriptor or residual, got '" +
                     o.placement + "'");
  if (!(o.sure_margin >= 1 && o.sure_margin < 100))
    throw UsageError("config key 'match.sure_margin' must be in [1, 100)");
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
  MatchShape shape{V, canonical, F, {}, lumped_masses(V, F), {}, 0};
  const auto start = std::chrono::steady_clock::now();
  if (options.placement == "descriptor") shape.curvature = mean_curvature_scales(V, F);
  if (options.refine == "zoomout") {
    if (options.spectral_size >= V.rows())
      throw InputError("a shape of " + std::to_string(V.rows()) +
                       " vertices is too small for match.spectral_size " +
                       std::to_string(options.spectral_size));
    shape.basis = laplace_beltrami_basis(V, F, options.spectral_size);
  }
  shape.seconds_basis = seconds_since(start);
  return shape;
}

namespace {

// Every (n / count)-th index of [0, n) (all of them when count is 0 or >= n).
std::vector<int> every_nth(Eigen::Index n, int count) {
  std::vector<int> rows;
  const Eigen::Index m = count <= 0 || count >= n ? n : count;
  for (Eigen::Index k = 0; k < m; ++k) rows.push_back(int(double(k) * double(n) / double(m)));
  return rows;
}

}  // namespace

ShapeMatch match_shapes(const MatchShape& source, const MatchShape& target,
                        const MatchOptions& options, const Eigen::Matrix3d* rotation_seed,
                        FormAlignments aligned) {
  validate_match_options(options);
  const bool zoom = options.refine == "zoomout";
  if (zoom && (source.basis.phi.cols() < options.spectral_size ||
               target.basis.phi.cols() < options.spectral_size))
    throw UsageError("match_shapes: a shape was prepared without its spectral basis");
  if (options.placement == "descriptor" &&
      (source.curvature.rows() != source.V.rows() || target.curvature.rows() != target.V.rows()))
    throw UsageError("match_shapes: a shape was prepared without its curvature descriptor");
  ZoomOutOptions zoom_options = options.zoomout;
  zoom_options.final_size = options.spectral_size;
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
  const FormAlignment* best[2] = {nullptr, nullptr};
  for (const FormAlignment& c : a.candidates) {
    const int side = c.mirrored;
    const bool better =
        !best[side] ||
        (c.seeded ? !best[side]->seeded : !best[side]->seeded && c.residual < best[side]->residual);
    if (better) best[side] = &c;
    if (!c.seeded && (!best_fit || c.residual < best_fit->residual)) best_fit = &c;
  }
  result.from_collection = best[0]->seeded;
  result.rigid = tree.nearest_rows(best_fit->moved);
  result.candidates = int(a.candidates.size());
  result.rotation_residual = best[0]->residual;
  result.mirrored_residual = best[1]->residual;
  const double ratio = best[1]->residual / best[0]->residual;
  result.mirrored =
      options.mirror == "off" ? best_fit->mirrored : ratio < 1 - options.mirror_margin;
  result.ambiguous =
      options.mirror != "off" && !result.mirrored && ratio < 1 / (1 - options.mirror_margin);
  const FormAlignment* chosen = options.mirror == "off" ? best_fit : best[int(result.mirrored)];

  // The placements of the chosen orientation, each refined on samples and
  // scored by the curvature descriptors its map disagrees with.
  Eigen::MatrixXd chosen_C;
  result.placement_margin = std::numeric_limits<double>::infinity();
  if (options.placement == "descriptor" && !result.from_collection) {
    const std::vector<int> rows = every_nth(source.V.rows(), options.zoomout.samples);
    const auto disagreement = [&](const Eigen::VectorXi& sampled) {
      return descriptor_disagreement(source.curvature, target.curvature, source.masses, rows,
                                     sampled);
    };
    // First by the placements' own nearest points: a body placed upside down
    // disagrees about twice as much as either of the two upright ones, which
    // only refined maps tell apart; those two are refined and compared.
    std::vector<std::pair<double, const FormAlignment*>> upright;
    for (const FormAlignment& c : a.candidates) {
      if (c.mirrored != chosen->mirrored || c.seeded) continue;
      const Eigen::MatrixX3d moved = c.moved(rows, Eigen::all);
      upright.emplace_back(disagreement(tree.nearest_rows(moved)), &c);
    }
    std::sort(upright.begin(), upright.end());
    if (upright.size() > 2) upright.resize(2);
    double first = std::numeric_limits<double>::infinity(), second = first;
    std::vector<Eigen::VectorXi> refined;  // the sampled maps, to see whether they differ
    for (const auto& [unrefined, candidate] : upright) {
      const FormAlignment& c = *candidate;
      ++result.placements;
      Eigen::MatrixXd C;
      double score = unrefined;
      if (zoom) {
        C = zoomout_functional_map(source.basis, target.basis, tree.nearest_rows(c.moved),
                                   zoom_options);
        refined.push_back(pointwise_map(source.basis, target.basis, C, rows));
        score = disagreement(refined.back());
      }
      if (score < first) {
        second = first;
        first = score;
        chosen = &c;
        chosen_C = std::move(C);
      } else {
        second = std::min(second, score);
      }
    }
    // Two placements that ZoomOut takes to one map (images within 2 % of
    // sqrt(area) of each other on average) leave nothing to decide.
    bool same_map = false;
    if (refined.size() == 2) {
      double apart = 0;
      for (Eigen::Index r = 0; r < refined[0].size(); ++r)
        apart += (target.V.row(refined[0](r)) - target.V.row(refined[1](r))).norm();
      same_map = apart / double(refined[0].size()) < 0.02 * std::sqrt(target.masses.sum());
    }
    if (result.placements > 1 && !same_map)
      result.placement_margin = first > 0    ? second / first
                                : second > 0 ? std::numeric_limits<double>::infinity()
                                             : 1.0;
    result.sure = result.placement_margin >= options.sure_margin;
  }
  result.rotation = chosen->linear;
  result.oriented = tree.nearest_rows(chosen->moved);
  char margin[80] = "";
  if (result.placements > 1)
    std::snprintf(margin, sizeof margin, "; %s, the next placement disagrees %.2fx",
                  result.sure ? "sure" : "unsure", result.placement_margin);
  char text[300];
  if (options.mirror == "off") {
    std::snprintf(text, sizeof text,
                  "%s (the better fit; the mirror image fits %.2fx the rotation%s)",
                  result.mirrored ? "mirrored" : "rotation", ratio, margin);
  } else {
    std::snprintf(text, sizeof text,
                  result.mirrored    ? "mirrored (the mirror image fits %.2fx the rotation%s%s)"
                  : result.ambiguous ? "ambiguous: kept the rotation (the mirror image fits %.2fx "
                                       "the rotation%s, within the margin%s)"
                                     : "rotation (the mirror image fits %.2fx the rotation%s%s)",
                  ratio, result.from_collection ? " placed by the collection" : "", margin);
  }
  result.decision = text;
  result.seconds_align = seconds_since(start);

  result.map = result.oriented;
  if (zoom) {
    start = std::chrono::steady_clock::now();
    if (chosen_C.size() == 0)
      chosen_C = zoomout_functional_map(source.basis, target.basis, result.oriented, zoom_options);
    result.map = pointwise_map(source.basis, target.basis, chosen_C);
    result.seconds_refine = seconds_since(start);
  }
  return result;
}

}  // namespace unfold
