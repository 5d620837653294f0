// One whole run (tetrahedralize -> lambda_2 -> cascade -> metrics) at a chosen
// size, for the scaling table of docs/performance.md (bench/run runs it once
// per size, each in its own process so that peak memory is per size).
//   build/bin/scale_bench (--input=MESH | --demo_resolution=R) [--volume_divisions=M]
//                         [--analyze_only] [--linear_solver=auto|direct|iterative]
//   build/bin/scale_bench --plot=CSV --output=PNG
// --volume_divisions=M bounds every tetrahedron's volume by (enclosed volume) / M
// (TetGen -a), which adds interior vertices: about M / 4.5 of them with the
// default quality bound. Prints one tab-separated row:
//   tet_vertices tets seconds_tet seconds_unfold seconds_metrics seconds_total
//   iterations linear_solver cg_iterations peak_rss_mb peak_rss_tetgen_mb E_rig edge_ratio
// (seconds_unfold: AMG setup, lambda_2 and the cascade; seconds_total: the
// whole unfold_surface call), then
//   seconds_read seconds_lambda2 seconds_cascade seconds_write surface_vertices E_str
//   seconds_interior seconds_integration seconds_anchored seconds_prepare seconds_contact
//   tet_shape
// (seconds_read: reading --input, 0 for the demo shape; seconds_lambda2: the
// solver's setup, AMG included, and lambda_2; seconds_write: the canonical
// surface as OFF and the metrics JSON, as `unfold --output --metrics_json`
// writes them, into a temporary folder). --metrics=E_rig,E_str (etc.) sets
// metrics.compute, --config=C.yaml a config (e.g. configs/invariant.yaml: its
// stages after the surface solve are seconds_interior, seconds_integration and
// seconds_anchored; 0 for the paper's method; seconds_prepare: prepare_mesh, the input's tets
// included when made; seconds_contact: tetrahedralize.shape auto's contact check; tet_shape:
// input or unfolded, whose seconds_tet are the unfolded shape's tets and their placement,
// inside seconds_unfold). --analyze_only stops after the direct solver's
// symbolic analysis and prints
//   tet_vertices tets seconds_tet seconds_analyze factor_nonzeros factor_gflops peak_rss_mb
// --stages prints, instead of the row, one tab-separated line per stage of the
// method's list (pipeline/run_stages.h) in order: name, seconds; then "whole
// run" (read, unfold_surface, write) and its seconds.
// --plot draws the scaling plot from bench/run's CSV (columns as the row above).
#include <glog/logging.h>
#include <sys/resource.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/keep_freed_memory.h"
#include "core/seconds_since.h"
#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "pipeline/metrics_json.h"
#include "pipeline/unfold_surface.h"
#include "render/plot_scaling.h"
#include "render/write_png.h"
#include "shapes/articulated_shape.h"
#include "solvers/sparse_ldlt.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

// Volume enclosed by a closed, consistently oriented surface (divergence
// theorem over a fan triangulation of each face).
double enclosed_volume(const SurfaceMesh& s) {
  double six_volume = 0;
  for (const auto& f : s.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k)
      six_volume += s.V.row(f[0]).dot(s.V.row(f[k]).cross(s.V.row(f[k + 1])));
  return std::abs(six_volume) / 6;
}

double peak_rss_mb(int who) {
  rusage usage{};
  getrusage(who, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

// The scaling plot from bench/run's CSV: a header line, then one row per size.
int plot(const std::string& csv, const std::string& png) {
  std::ifstream in(csv);
  if (!in) throw UsageError("scale_bench: cannot read '" + csv + "'");
  std::string line;
  std::getline(in, line);  // header
  std::vector<double> n, tet, unfold, metrics, total, memory;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.size() < 11) throw UsageError("scale_bench: short row in '" + csv + "': " + line);
    n.push_back(std::stod(cells[0]));
    tet.push_back(std::stod(cells[2]));
    unfold.push_back(std::stod(cells[3]));
    metrics.push_back(std::stod(cells[4]));
    total.push_back(std::stod(cells[5]));
    memory.push_back(std::max(std::stod(cells[9]), std::stod(cells[10])));
  }
  write_png(png, plot_scaling(n,
                              {{"whole run", total},
                               {"unfolding (tets of the default)", unfold},
                               {"tets", tet},
                               {"metrics", metrics}},
                              memory));
  return 0;
}

int run(int argc, char** argv) {
  std::string input, plot_csv, output, linear_solver = "auto", metrics, config;
  int resolution = 0;
  double divisions = 0;
  bool analyze_only = false, stages = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const size_t eq = arg.find('=');
    const std::string key = arg.substr(0, eq),
                      value = eq == std::string::npos ? "" : arg.substr(eq + 1);
    if (key == "--input")
      input = value;
    else if (key == "--demo_resolution")
      resolution = std::stoi(value);
    else if (key == "--volume_divisions")
      divisions = std::stod(value);
    else if (key == "--analyze_only")
      analyze_only = true;
    else if (key == "--stages")
      stages = true;
    else if (key == "--linear_solver")
      linear_solver = value;
    else if (key == "--metrics")
      metrics = value;
    else if (key == "--config")
      config = value;
    else if (key == "--plot")
      plot_csv = value;
    else if (key == "--output")
      output = value;
    else
      throw UsageError("scale_bench: unknown argument '" + arg + "'");
  }
  if (!plot_csv.empty()) return plot(plot_csv, output);
  if (input.empty() == (resolution == 0))
    throw UsageError("scale_bench: give exactly one of --input and --demo_resolution");
  const auto read_start = std::chrono::steady_clock::now();
  const SurfaceMesh surface = input.empty()
                                  ? make_articulated_shape(ShapePose::preset(0), resolution)
                                  : read_surface_mesh(input);
  const double seconds_read = input.empty() ? 0 : seconds_since(read_start);
  std::map<std::string, std::string> overrides;
  if (config.empty() || linear_solver != "auto") overrides["linear_solver.method"] = linear_solver;
  if (!metrics.empty()) overrides["metrics.compute"] = metrics;
  Options options = load_options(config, overrides);
  if (divisions > 0) options.tet.max_volume = enclosed_volume(surface) / divisions;
  if (analyze_only) {
    TetReport report;
    const TetMesh tets = tetrahedralize(surface, options.tet, &report);
    const auto start = std::chrono::steady_clock::now();
    const EdgeGraph graph = build_edge_graph(int(tets.V.rows()), tets.T);
    SparseLdlt ldlt;
    ldlt.analyze(graph_laplacian(graph));
    const double seconds = seconds_since(start);
    std::printf("%d\t%d\t%.3f\t%.3f\t%.0f\t%.2f\t%.0f\n", int(tets.V.rows()), int(tets.T.rows()),
                report.seconds, seconds, ldlt.factor_nonzeros(), ldlt.factor_flops() / 1e9,
                peak_rss_mb(RUSAGE_SELF));
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  const UnfoldResult r = unfold_surface(surface, options);
  const double total = seconds_since(start);
  const std::string dir = std::filesystem::temp_directory_path().string() + "/scale_bench_" +
                          std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  const auto write_start = std::chrono::steady_clock::now();
  write_surface_mesh(dir + "/canonical.off", r.canonical);
  write_metrics_json(dir + "/metrics.json", r, options);
  const double seconds_write = seconds_since(write_start);
  std::filesystem::remove_all(dir);
  if (stages) {
    for (const StageTime& stage : r.stage_seconds)
      std::printf("%s\t%.3f\n", stage.name.c_str(), stage.seconds);
    std::printf("whole run\t%.3f\n", seconds_read + total + seconds_write);
    return 0;
  }
  std::printf(
      "%d\t%d\t%.3f\t%.3f\t%.3f\t%.3f\t%d\t%s\t%d\t%.0f\t%.0f\t%.4f\t%.4f\t%.3f\t%.3f\t%.3f\t%."
      "3f\t%d\t%."
      "4f\t%.3f\t%.3f\t%.3f\t%.3f\t%.3f\t%s\n",
      int(r.tets.V.rows()), int(r.tets.T.rows()), r.tet_report.seconds, r.seconds_unfold,
      r.metrics.seconds, total, r.cascade.iterations, r.linear_solver.c_str(), r.cg.iterations,
      peak_rss_mb(RUSAGE_SELF), peak_rss_mb(RUSAGE_CHILDREN), r.metrics.E_rig, r.cascade.edge_ratio,
      seconds_read, r.seconds_lambda2, r.seconds_cascade, seconds_write, int(r.surface.V.rows()),
      r.metrics.E_str, r.seconds_interior, r.seconds_integration, r.seconds_anchored,
      r.seconds_prepare, r.seconds_contact, r.tet_report.shape.c_str());
  return 0;
}

}  // namespace
}  // namespace unfold

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  FLAGS_minloglevel = 1;
  unfold::keep_freed_memory();  // as the apps do: their stages' timings
  try {
    return unfold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scale_bench: %s\n", e.what());
    return 1;
  }
}
