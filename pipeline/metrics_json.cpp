#include "pipeline/metrics_json.h"

#include <cmath>
#include <ostream>

#include "core/atomic_file.h"

namespace unfold {

Json metrics_document(const UnfoldResult& r, const Options& options) {
  const UnfoldMetrics& m = r.metrics;
  const CascadeResult& c = r.cascade;
  JsonArray warnings(r.warnings.begin(), r.warnings.end());
  JsonObject stages;  // every stage run, in order (pipeline/run_stages.h)
  for (const StageTime& t : r.stage_seconds) stages.emplace_back(t.name, t.seconds);
  JsonArray history;
  for (const IterationRecord& h : c.history)
    history.push_back(JsonObject{{"iteration", h.iteration},
                                 {"cascade", h.cascade},
                                 {"beta", h.beta},
                                 {"energy", h.energy},
                                 {"edge_ratio", h.edge_ratio}});
  // E_rig, E_str, E_geo and E_geo_surface not computed are NaN, written as null;
  // E_geo_skipped is null, or why E_geo was left out and how to ask for it.
  return JsonObject{
      {"metrics_computed", JsonArray(options.metrics.begin(), options.metrics.end())},
      {"E_rig", m.E_rig},
      {"E_str", m.E_str},
      {"E_str_exact", m.E_str_exact},
      {"E_geo", m.E_geo},
      {"E_geo_exact", m.E_geo_exact},
      {"E_geo_surface", m.E_geo_surface},
      {"E_geo_skipped", m.E_geo_skipped.empty() ? Json(std::nan("")) : Json(m.E_geo_skipped)},
      {"edge_ratio", c.edge_ratio},
      {"inverted_tets", m.inverted_tets},
      // What untangle.sweeps did before they were counted (all 0: off).
      {"untangle", JsonObject{{"inverted_before", r.untangle.inverted_before},
                              {"passes", r.untangle.sweeps},
                              {"moved_vertices", r.untangle.moved_vertices},
                              {"largest_move", r.untangle.largest_move}}},
      // The damage measure (metrics/surface_damage.h), always computed.
      {"damaged_edges_percent", m.damage.damaged_edges_percent},
      {"surface_edge_ratio_p999", m.damage.ratio_p999},
      {"surface_edge_ratio_max", m.damage.ratio_max},
      {"surface_edge_ratio_min", m.damage.ratio_min},
      {"damaged_surface_edges", m.damage.damaged_edges},
      {"surface_edges_measured", m.damage.edges},
      {"zero_length_surface_edges", m.damage.zero_length_edges},
      // The fold measure (metrics/surface_folds.h), always computed.
      {"folded_edges_percent", m.folds.folded_edges_percent},
      {"folded_surface_edges", m.folds.folded_edges},
      {"dihedral_change_p999_degrees", m.folds.dihedral_change_p999},
      {"dihedral_change_max_degrees", m.folds.dihedral_change_max},
      {"final_energy", c.final_energy},
      {"reached_band", c.reached_band},
      {"bounded", c.bounded},
      {"iterations", c.iterations},
      {"cascades", c.cascades},
      {"beta", c.final_beta},
      {"beta_start", r.beta_start},
      {"beta_requested", r.beta_requested},
      {"beta_raised", r.beta_raised},
      {"lambda2", r.lambda2},
      {"surface_vertices", int64_t(r.surface.V.rows())},
      {"surface_faces", int64_t(r.surface.faces.size())},
      {"tet_vertices", int64_t(r.tets.V.rows())},
      {"tets", int64_t(r.tets.T.rows())},
      {"edges", r.num_edges},
      {"linear_solver", JsonObject{{"method", r.linear_solver},
                                   {"amg_levels", r.amg_levels},
                                   {"cg_solves", r.cg.solves},
                                   {"cg_iterations", r.cg.iterations},
                                   {"cg_unconverged_solves", r.cg.unconverged_solves},
                                   {"cg_worst_relative_residual", r.cg.worst_relative_residual},
                                   {"seconds_amg", r.seconds_amg}}},
      {"tetrahedralization",
       JsonObject{{"route", r.tet_report.route},
                  {"tets", r.tet_report.num_tets},
                  {"interior_points", r.tet_report.num_interior_points},
                  {"removed_tets", r.tet_report.num_removed_tets},
                  {"rescued_tets", r.tet_report.num_rescued_tets},
                  {"intersecting_faces", r.tet_report.num_intersecting_faces},
                  {"fallback", r.tet_report.fallback},
                  {"shape", r.tet_report.shape},
                  {"dropped_inverted_tets", r.tet_report.dropped_inverted_tets},
                  {"dropped_flat_tets", r.tet_report.dropped_flat_tets},
                  {"inverted_rest_tets", r.tet_report.inverted_rest_tets},
                  {"contact_face_pairs", r.tet_report.contact_face_pairs},
                  {"contact_bridge", r.tet_report.contact_bridge},
                  {"seconds", r.tet_report.seconds}}},
      {"seconds_tetrahedralize", r.tet_report.seconds},
      {"seconds_prepare", r.seconds_prepare},
      {"seconds_contact", r.seconds_contact},
      {"seconds_unfold", r.seconds_unfold},
      {"seconds_lambda2", r.seconds_lambda2},
      {"seconds_cascade", r.seconds_cascade},
      {"seconds_interior", r.seconds_interior},
      {"seconds_integration", r.seconds_integration},
      {"seconds_anchored", r.seconds_anchored},
      {"anchored_steps", r.anchored_steps},
      {"anchored_converged", r.anchored_converged},
      {"seconds_metrics", m.seconds},
      {"stages", stages},
      {"method", options.method},
      {"warnings", warnings},
      {"history", history}};
}

void write_metrics_json(const std::string& path, const UnfoldResult& result,
                        const Options& options) {
  write_file_atomically(
      path, [&](std::ostream& out) { out << to_json_text(metrics_document(result, options)); });
}

}  // namespace unfold
