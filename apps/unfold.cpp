// unfold: a surface mesh in, its canonical pose out.
// Flags and config only; the work is unfold_surface() in the library.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "apps/app_main.h"
#include "apps/config_flags.h"
#include "config/options.h"
#include "core/atomic_file.h"
#include "core/output_transaction.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/read_tet_mesh.h"
#include "mesh/tet_mesh_boundary.h"
#include "mesh/write_polyline.h"
#include "mesh/write_surface_mesh.h"
#include "mesh/write_tet_mesh.h"
#include "metrics/worst_region.h"
#include "pipeline/beta_sweep.h"
#include "pipeline/convergence_csv.h"
#include "pipeline/metrics_json.h"
#include "pipeline/prepare_mesh_from_tets.h"
#include "pipeline/region_pictures.h"
#include "pipeline/result_pictures.h"
#include "pipeline/tet_fields.h"
#include "pipeline/unfold_surface.h"
#include "render/camera.h"
#include "render/plot_convergence.h"
#include "render/write_png.h"
#include "shapes/articulated_shape.h"

DEFINE_string(input, "",
              "surface mesh to unfold (.off .obj .ply .stl); empty: the built-in demo shape");
DEFINE_string(demo_pose, "0",
              "pose of the built-in demo shape when --input is empty: rest, 0, 1, 2");
DEFINE_string(output, "",
              "canonical surface (.off .obj .ply .stl): the input's vertices and faces");
DEFINE_string(input_copy, "", "also write the surface that was unfolded (e.g. the demo shape)");
DEFINE_string(tet_input, "",
              "a tet mesh to unfold instead of tetrahedralizing (.vtu as --tet_output writes it, "
              "TetGen .node/.ele, Gmsh .msh, MEDIT .mesh; ASCII); its boundary is the surface, "
              "or it holds --input's vertices (a carved tet mesh: a warning)");
DEFINE_string(tet_output, "", "canonical tet mesh: .vtu (ParaView) or .node (TetGen .node/.ele)");
DEFINE_string(rest_tet_output, "",
              "the tet mesh the run unfolded, at rest (.vtu or .node): to keep, inspect, or give "
              "back with --tet_input (by default the unfolded shape's tets put into the input; "
              "a .vtu also keeps where they were made, point array 'unfolded', and given back "
              "unfolds as the run did; a .node as with --tet_shape input)");
DEFINE_string(skeleton_output, "",
              "method scf: the input's curve skeleton as line segments (.vtk or .ply)");
DEFINE_string(canonical_skeleton_output, "",
              "method scf: the straightened skeleton, placed like --output (.vtk or .ply)");
DEFINE_string(metrics_json, "", "metrics, timings and the per-iteration history as JSON");
DEFINE_string(render, "",
              "before/after picture (.png): side and top views of the input and the canonical "
              "pose, same framing; with --beta_sweep the sweep instead");
DEFINE_string(render_color, "shading",
              "colouring of the canonical pose in --render: shading, rigidity (per-vertex "
              "rigidity error), or damage (per vertex the largest |ln r| of its surface edges' "
              "length ratios at the input's area; ln 3 = 1.1 is the damage bound), or folds (per "
              "vertex the largest sharpening of its edges' dihedral angles, degrees; folded beyond "
              "90)");
DEFINE_string(render_focus, "",
              "--render a close-up of one region instead of the whole shape: 'worst' (the vertex "
              "with the most stretched or crushed surface edge; with --render_color folds the "
              "most folded one) or a vertex index; the input and "
              "the canonical pose each seen face on, whatever lies in front of it cut away");
DEFINE_double(render_focus_radius, unfold::kRegionRadiusFraction,
              "--render_focus: the region's radius as a fraction of the input's bounding-box "
              "diagonal, in (0, 1] (on the canonical pose at the input's area)");
DEFINE_bool(render_skeleton, false,
            "method scf: draw the curve skeleton in --render (the input's over the input, the "
            "straightened one over the canonical pose)");
DEFINE_string(render_up, "z", "the shape's up axis for --render: x, y or z (TOSCA: z, FAUST: y)");
DEFINE_string(beta_sweep, "",
              "comma-separated betas relative to n/lambda_2 (e.g. 0.5,1,2,4): unfold once per "
              "beta on the same tet mesh and render them side by side into --render");
DEFINE_string(convergence, "", "energy and edge ratio per iteration as CSV");
DEFINE_string(convergence_png, "",
              "plot (.png) of the energy and edge ratio per iteration, cascade boundaries marked");
DEFINE_string(config, "", "YAML config; empty: the built-in defaults (= configs/default.yaml)");
DEFINE_bool(progress, true,
            "on a terminal: a progress line (stage, iterations, elapsed time) rewritten in place "
            "on stderr; none when stderr is a file or a pipe");

namespace {

int run() {
  unfold::Options options = unfold::load_options(FLAGS_config, config_flag_overrides());
  // E_geo (256 Dijkstras) costs more than the rest of the metrics together:
  // unfold computes it by default only up to this many tet vertices, unless
  // --metrics asks for the metrics or the limit is set (docs/usage.md).
  constexpr int kGeodesicDefaultMaxVertices = 20000;
  if (FLAGS_metrics.empty() && options.geodesic_max_vertices == 0 &&
      FLAGS_geodesic_max_vertices.empty())
    options.geodesic_max_vertices = kGeodesicDefaultMaxVertices;
  if (options.threads > 0) omp_set_num_threads(options.threads);
  // Refuse unsupported output formats before any work.
  for (const std::string& path : {FLAGS_output, FLAGS_input_copy})
    if (!path.empty()) unfold::check_surface_mesh_format(path);
  unfold::check_tet_mesh_format(FLAGS_tet_output);
  unfold::check_tet_mesh_format(FLAGS_rest_tet_output);
  for (const std::string& path : {FLAGS_skeleton_output, FLAGS_canonical_skeleton_output}) {
    if (path.empty()) continue;
    if (options.method != "scf")
      throw unfold::UsageError(
          "--skeleton_output and --canonical_skeleton_output need method: scf");
    unfold::check_polyline_format(path);
  }
  unfold::check_png_format(FLAGS_render);
  unfold::check_png_format(FLAGS_convergence_png);
  for (const std::string& path :
       {FLAGS_output, FLAGS_input_copy, FLAGS_tet_output, FLAGS_rest_tet_output, FLAGS_metrics_json,
        FLAGS_render, FLAGS_convergence, FLAGS_convergence_png, FLAGS_skeleton_output,
        FLAGS_canonical_skeleton_output})
    if (!path.empty()) unfold::check_writable_destination(path);
  unfold::RenderOptions render;
  render.up_axis = unfold::axis_index(FLAGS_render_up, "--render_up");
  try {
    unfold::surface_coloring(FLAGS_render_color);
  } catch (const unfold::UsageError& e) {
    throw unfold::UsageError(std::string("--render_color: ") + e.what());
  }
  if (FLAGS_render_color == "rigidity" && !unfold::computes_metric(options, "E_rig"))
    throw unfold::UsageError("--render_color rigidity needs E_rig in metrics.compute (--metrics)");
  if (FLAGS_render_skeleton &&
      (options.method != "scf" || FLAGS_render.empty() || !FLAGS_beta_sweep.empty()))
    throw unfold::UsageError(
        "--render_skeleton needs method: scf and --render, without --beta_sweep");
  // --render_focus: -1 for the worst region, else the vertex; none: the whole shape.
  std::optional<int> focus;
  if (!FLAGS_render_focus.empty()) {
    if (FLAGS_render.empty() || !FLAGS_beta_sweep.empty() || FLAGS_render_skeleton)
      throw unfold::UsageError(
          "--render_focus needs --render, without --beta_sweep or --render_skeleton");
    if (FLAGS_render_focus == "worst") {
      focus = -1;
    } else {
      const std::string& text = FLAGS_render_focus;
      if (text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        throw unfold::UsageError("--render_focus: '" + text +
                                 "' is neither 'worst' nor a vertex index");
      focus = std::stoi(text);
    }
  }
  if (!(FLAGS_render_focus_radius > 0 && FLAGS_render_focus_radius <= 1))
    throw unfold::UsageError("--render_focus_radius: " + std::to_string(FLAGS_render_focus_radius) +
                             " is not in (0, 1]");
  std::vector<double> sweep;
  if (!FLAGS_beta_sweep.empty()) {
    sweep = unfold::parse_beta_list(FLAGS_beta_sweep);
    if (FLAGS_render.empty())
      throw unfold::UsageError("--beta_sweep needs --render (the picture it makes)");
  }

  if (!FLAGS_tet_input.empty()) unfold::check_tet_input_format(FLAGS_tet_input);
  unfold::app::ProgressScope progress("unfold", FLAGS_progress);
  unfold::SurfaceMesh surface;
  unfold::TetMeshData given_tets;
  if (!FLAGS_tet_input.empty()) {
    given_tets = unfold::read_tet_mesh(FLAGS_tet_input);
    surface = FLAGS_input.empty() ? unfold::tet_mesh_boundary(given_tets.V, given_tets.T)
                                  : unfold::read_surface_mesh(FLAGS_input);
  } else if (FLAGS_input.empty()) {
    LOG(INFO) << "no --input: unfolding the built-in demo shape, pose " << FLAGS_demo_pose;
    surface = unfold::make_articulated_shape(unfold::ShapePose::named(FLAGS_demo_pose));
  } else {
    surface = unfold::read_surface_mesh(FLAGS_input);
  }
  // Simplification renumbers the vertices; otherwise refuse a bad index before the work.
  if (focus && *focus >= surface.V.rows() && options.target_vertices == 0)
    throw unfold::UsageError("--render_focus: vertex " + std::to_string(*focus) +
                             " is not in [0, " + std::to_string(surface.V.rows()) + ")");
  const unfold::UnfoldResult result =
      FLAGS_tet_input.empty() ? unfold::unfold_surface(surface, options)
                              : unfold::unfold_prepared(unfold::prepare_mesh_from_tets(
                                                            surface, given_tets.V, given_tets.T,
                                                            options, given_tets.unfolded),
                                                        options);

  const bool wants_skeleton =
      !FLAGS_skeleton_output.empty() || !FLAGS_canonical_skeleton_output.empty();
  if (wants_skeleton && result.skeleton.nodes.rows() == 0)
    throw unfold::UsageError(
        "--skeleton_output: no single skeleton (components: separately unfolds each apart)");
  unfold::report_stage("writing the outputs");
  unfold::OutputTransaction outputs;  // all files or none (docs/errors.md)
  if (!FLAGS_output.empty()) unfold::write_surface_mesh(FLAGS_output, result.canonical);
  if (!FLAGS_input_copy.empty()) unfold::write_surface_mesh(FLAGS_input_copy, result.surface);
  if (!FLAGS_tet_output.empty())
    unfold::write_tet_mesh(FLAGS_tet_output, result.tet_canonical, result.tets.T,
                           unfold::canonical_tet_fields(result));
  if (!FLAGS_rest_tet_output.empty())
    unfold::write_tet_mesh(FLAGS_rest_tet_output, result.tets.V, result.tets.T,
                           unfold::rest_tet_fields(result));
  if (!FLAGS_skeleton_output.empty())
    unfold::write_polyline(FLAGS_skeleton_output, result.skeleton.nodes, result.skeleton.edges);
  if (!FLAGS_canonical_skeleton_output.empty())
    unfold::write_polyline(FLAGS_canonical_skeleton_output, result.skeleton_canonical,
                           result.skeleton.edges);
  if (!FLAGS_metrics_json.empty()) unfold::write_metrics_json(FLAGS_metrics_json, result, options);
  if (!FLAGS_convergence.empty())
    unfold::write_convergence_csv(FLAGS_convergence, result.cascade.history);
  if (!FLAGS_convergence_png.empty())
    unfold::write_png(
        FLAGS_convergence_png,
        unfold::plot_convergence(result.cascade.history, options.cascade.edge_ratio_band));
  if (!sweep.empty())
    unfold::write_png(FLAGS_render,
                      unfold::render_beta_sweep(unfold::unfold_beta_sweep(result, options, sweep),
                                                sweep, render));
  else if (focus)
    unfold::write_png(FLAGS_render, unfold::render_region_before_after(
                                        result, *focus, FLAGS_render_focus_radius, render.up_axis,
                                        unfold::surface_coloring(FLAGS_render_color)));
  else if (!FLAGS_render.empty())
    unfold::write_png(
        FLAGS_render,
        unfold::render_before_after(result, render, unfold::surface_coloring(FLAGS_render_color),
                                    FLAGS_render_skeleton));
  outputs.commit();
  progress.finish();

  const auto& m = result.metrics;
  const auto metric = [](const char* name, double value) {  // NaN: not computed
    char text[64];
    if (std::isnan(value))
      std::snprintf(text, sizeof text, "%s not computed", name);
    else
      std::snprintf(text, sizeof text, "%s %.3f", name, value);
    return std::string(text);
  };
  // E_geo over the surface alone, beside E_geo when it was computed.
  char surface_geo[48] = "";
  if (!std::isnan(m.E_geo_surface))
    std::snprintf(surface_geo, sizeof surface_geo, " (over the surface %.3f)", m.E_geo_surface);
  std::printf(
      "unfolded %d surface vertices (%d tet vertices, %d tets; %s route, %d intersecting face "
      "pairs) in %.2f s: %s, %s, %s%s, edge ratio %.3f, %d cascades, %d iterations%s; damaged "
      "surface edges %.3f %% (ratio outside [1/%g, %g]; ratio p99.9 %.2f, max %.2f, min %.3f), "
      "%d inverted tets; folded surface edges %.3f %% (bend sharpened by more than %g "
      "degrees; p99.9 %.0f, max %.0f)\n",
      int(result.surface.V.rows()), int(result.tets.V.rows()), int(result.tets.T.rows()),
      result.tet_report.route.c_str(), result.tet_report.num_intersecting_faces,
      result.seconds_prepare + result.seconds_unfold, metric("E_rig", m.E_rig).c_str(),
      metric("E_str", m.E_str).c_str(),
      m.E_geo_skipped.empty() ? metric("E_geo", m.E_geo).c_str() : m.E_geo_skipped.c_str(),
      surface_geo, result.cascade.edge_ratio, result.cascade.cascades, result.cascade.iterations,
      result.cascade.reached_band ? "" : " (edge-ratio band not reached)",
      m.damage.damaged_edges_percent, unfold::kDamagedEdgeRatio, unfold::kDamagedEdgeRatio,
      m.damage.ratio_p999, m.damage.ratio_max, m.damage.ratio_min, m.inverted_tets,
      m.folds.folded_edges_percent, unfold::kFoldedDegrees, m.folds.dihedral_change_p999,
      m.folds.dihedral_change_max);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetVersionString("0.1.0");
  unfold::app::AppHelp help;
  help.usage = "unfold [--input shape.off] --output canonical.off [--config c.yaml] [flags]";
  help.summary =
      "Unfolds a non-rigid shape into its canonical pose. Without --input it unfolds the built-in "
      "demo shape. Every config key is also a flag, overriding --config.";
  help.groups = {
      {"Input and output",
       {"input", "demo_pose", "tet_input", "output", "input_copy", "tet_output", "rest_tet_output",
        "metrics_json", "convergence", "skeleton_output", "canonical_skeleton_output", "progress"}},
      {"Method and config", {"config"}},
      {"Cascade", {}},
      {"Tetrahedralization", {}},
      {"Linear solver (method local_global)", {}},
      {"Energy terms", {}},
      {"Metrics and pictures",
       {"render", "render_color", "render_skeleton", "render_up", "render_focus",
        "render_focus_radius", "beta_sweep", "convergence_png"}},
  };
  help.config_key_flags = true;
  return unfold::app::run_main("unfold", help, argc, argv, run);
}
