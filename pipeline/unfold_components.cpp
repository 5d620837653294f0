#include "pipeline/unfold_components.h"

#include <glog/logging.h>

#include <algorithm>

#include "core/errors.h"
#include "mesh/split_surface_components.h"

namespace unfold {
namespace {

UnfoldResult unfold_part(const SurfaceMesh& part, const Options& options, int number) {
  const std::string where = "component " + std::to_string(number) + ": ";
  try {
    return unfold_surface(part, options);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  } catch (const NumericalError& e) {
    throw NumericalError(where + e.what());
  }
}

// Copies row i of `from` to row map[i] of `to`: every per-vertex field of a
// part goes into the merged one through this.
template <typename Field>
void scatter_rows(const Field& from, const std::vector<int>& map, Field* to) {
  for (Eigen::Index i = 0; i < from.rows(); ++i) to->row(map[size_t(i)]) = from.row(i);
}

// Where each part's tet vertices go in the merged tet mesh: surface vertices
// first (input order, or the parts one after the other when simplified), then
// every part's interior vertices.
std::vector<std::vector<int>> merged_vertex_maps(const std::vector<SurfaceComponent>& components,
                                                 const std::vector<UnfoldResult>& parts,
                                                 bool simplified) {
  int interior = 0;
  for (const auto& r : parts) interior += r.tets.num_surface_vertices;
  std::vector<std::vector<int>> maps(parts.size());
  for (size_t c = 0, surface = 0; c < parts.size(); ++c) {
    const TetMesh& tets = parts[c].tets;
    for (int v = 0; v < int(tets.V.rows()); ++v)
      maps[c].push_back(v >= tets.num_surface_vertices ? interior++
                        : simplified                   ? int(surface) + v
                                                       : components[c].vertices[size_t(v)]);
    surface += size_t(tets.num_surface_vertices);
  }
  return maps;
}

// The parts as one result: per-vertex fields concatenated through `maps`,
// counts and times summed, figures combined as documented in the header.
UnfoldResult merge_results(const std::vector<UnfoldResult>& parts,
                           const std::vector<std::vector<int>>& maps) {
  Eigen::Index num_surface = 0, num_tet_vertices = 0, num_tets = 0;
  for (const auto& r : parts) {
    num_surface += r.tets.num_surface_vertices;
    num_tet_vertices += r.tets.V.rows();
    num_tets += r.tets.T.rows();
  }
  UnfoldResult merged;
  merged.surface.V.resize(num_surface, 3);
  merged.canonical.V.resize(num_surface, 3);
  merged.tets.V.resize(num_tet_vertices, 3);
  merged.tets.T.resize(num_tets, 4);
  merged.tets.num_surface_vertices = int(num_surface);
  merged.tet_canonical.resize(num_tet_vertices, 3);
  merged.tet_report.route = parts.front().tet_report.route;
  merged.lambda2 = parts.front().lambda2;
  merged.linear_solver = parts.front().linear_solver;
  merged.beta_requested = merged.beta_start = parts.front().beta_start;
  merged.warnings.push_back(std::to_string(parts.size()) +
                            " connected components unfolded separately");
  CascadeResult& cascade = merged.cascade;
  cascade.reached_band = true;
  UnfoldMetrics& m = merged.metrics;
  m.rigidity_per_vertex.resize(num_tet_vertices);
  double edge_ratio_sum = 0, str_sum = 0, geo_sum = 0, surface_geo_sum = 0;
  Eigen::Index tet_row = 0;
  for (size_t c = 0; c < parts.size(); ++c) {
    const UnfoldResult& r = parts[c];
    const std::vector<int>& map = maps[c];
    const std::vector<int> surface_map(map.begin(), map.begin() + r.tets.num_surface_vertices);
    scatter_rows(r.surface.V, surface_map, &merged.surface.V);
    scatter_rows(r.canonical.V, surface_map, &merged.canonical.V);
    scatter_rows(r.tets.V, map, &merged.tets.V);
    scatter_rows(r.tet_canonical, map, &merged.tet_canonical);
    scatter_rows(r.metrics.rigidity_per_vertex, map, &m.rigidity_per_vertex);
    for (Eigen::Index t = 0; t < r.tets.T.rows(); ++t, ++tet_row)
      for (int k = 0; k < 4; ++k) merged.tets.T(tet_row, k) = map[size_t(r.tets.T(t, k))];
    for (auto face : r.surface.faces) {
      for (int& v : face) v = surface_map[size_t(v)];
      merged.surface.faces.push_back(face);
    }
    if (r.tet_report.route != merged.tet_report.route) merged.tet_report.route = "mixed";
    merged.tet_report.num_tets += r.tet_report.num_tets;
    merged.tet_report.num_interior_points += r.tet_report.num_interior_points;
    merged.tet_report.num_intersecting_faces += r.tet_report.num_intersecting_faces;
    merged.tet_report.seconds += r.tet_report.seconds;
    merged.num_edges += r.num_edges;
    merged.lambda2 = std::min(merged.lambda2, r.lambda2);
    merged.beta_requested = std::min(merged.beta_requested, r.beta_requested);
    merged.beta_start = std::min(merged.beta_start, r.beta_start);
    merged.beta_raised = merged.beta_raised || r.beta_raised;
    merged.seconds_unfold += r.seconds_unfold;
    merged.seconds_prepare += r.seconds_prepare;
    merged.seconds_contact += r.seconds_contact;
    merged.seconds_lambda2 += r.seconds_lambda2;
    merged.seconds_cascade += r.seconds_cascade;
    for (const StageTime& stage : r.stage_seconds) {  // each stage's seconds summed over components
      auto same = std::find_if(merged.stage_seconds.begin(), merged.stage_seconds.end(),
                               [&stage](const StageTime& t) { return t.name == stage.name; });
      if (same == merged.stage_seconds.end())
        merged.stage_seconds.push_back(stage);
      else
        same->seconds += stage.seconds;
    }
    if (r.linear_solver != merged.linear_solver) merged.linear_solver = "mixed";
    merged.amg_levels = std::max(merged.amg_levels, r.amg_levels);
    merged.seconds_amg += r.seconds_amg;
    merged.cg.solves += r.cg.solves;
    merged.cg.iterations += r.cg.iterations;
    merged.cg.unconverged_solves += r.cg.unconverged_solves;
    merged.cg.worst_relative_residual =
        std::max(merged.cg.worst_relative_residual, r.cg.worst_relative_residual);
    merged.anchored_steps = std::max(merged.anchored_steps, r.anchored_steps);
    merged.anchored_converged = merged.anchored_converged && r.anchored_converged;
    for (const auto& w : r.warnings)
      merged.warnings.push_back("component " + std::to_string(c + 1) + ": " + w);

    for (IterationRecord h : r.cascade.history) {
      h.iteration += cascade.iterations;
      cascade.history.push_back(h);
    }
    cascade.iterations += r.cascade.iterations;
    cascade.cascades = std::max(cascade.cascades, r.cascade.cascades);
    cascade.final_beta = std::max(cascade.final_beta, r.cascade.final_beta);
    cascade.reached_band = cascade.reached_band && r.cascade.reached_band;
    cascade.bounded = cascade.bounded && r.cascade.bounded;
    edge_ratio_sum += r.cascade.edge_ratio * r.num_edges;
    str_sum += r.metrics.E_str * double(r.tets.V.rows());
    geo_sum += r.metrics.E_geo * double(r.tets.V.rows());
    surface_geo_sum += r.metrics.E_geo_surface * double(r.tets.num_surface_vertices);
    m.E_str_exact = m.E_str_exact && r.metrics.E_str_exact;
    m.E_geo_exact = m.E_geo_exact && r.metrics.E_geo_exact;
    m.inverted_tets += r.metrics.inverted_tets;
    UntangleReport& u = merged.untangle;
    u.inverted_before += r.untangle.inverted_before;
    u.inverted_after += r.untangle.inverted_after;
    u.moved_vertices += r.untangle.moved_vertices;
    u.largest_move = std::max(u.largest_move, r.untangle.largest_move);
    u.sweeps = std::max(u.sweeps, r.untangle.sweeps);
    m.seconds += r.metrics.seconds;
  }
  merged.canonical.faces = merged.surface.faces;
  cascade.edge_ratio = edge_ratio_sum / merged.num_edges;
  cascade.positions = merged.tet_canonical.rowwise() - merged.tet_canonical.colwise().mean();
  m.E_rig = m.rigidity_per_vertex.mean();  // E_rig is a mean over tet vertices (Eq. 8)
  m.E_str = str_sum / double(num_tet_vertices);
  m.E_geo = geo_sum / double(num_tet_vertices);
  m.E_geo_surface = surface_geo_sum / double(num_surface);
  return merged;
}

}  // namespace

UnfoldResult unfold_components_separately(const SurfaceMesh& surface, const Options& options) {
  const std::vector<SurfaceComponent> components = split_surface_components(surface);
  LOG(INFO) << "unfolding " << components.size() << " connected components separately";
  Options part_options = options;
  part_options.components = "refuse";
  std::vector<UnfoldResult> parts;
  for (size_t c = 0; c < components.size(); ++c)
    parts.push_back(unfold_part(components[c].mesh, part_options, int(c) + 1));
  bool simplified = false;
  for (size_t c = 0; c < parts.size(); ++c)
    simplified = simplified || parts[c].surface.V.rows() != components[c].mesh.V.rows();
  UnfoldResult merged = merge_results(parts, merged_vertex_maps(components, parts, simplified));
  // Unsimplified, the merged surface is the input itself, faces in input order.
  if (!simplified) merged.surface.faces = merged.canonical.faces = surface.faces;
  // The damage measure over the merged surface, as over any output surface
  // (one area scale for the whole; per vertex, the merged surface's vertices).
  merged.metrics.damage =
      surface_damage(merged.surface.V, merged.canonical.V, merged.surface.faces);
  merged.metrics.folds =
      surface_folds(merged.surface.V, merged.canonical.V, triangulate_faces(merged.surface));
  return merged;
}

}  // namespace unfold
