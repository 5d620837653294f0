// One whole run (tetrahedralize -> lambda_2 -> cascade -> metrics) at a chosen
// size, for the scaling table of docs/performance.md (bench/run runs it once
// per size, each in its own process so that peak memory is per size).
//   build/bin/scale_bench (--input=MESH | --demo_resolution=R) [--volume_divisions=M]
//                         [--analyze_only]
// --volume_divisions=M bounds every tetrahedron's volume by (enclosed volume) / M
// (TetGen -a), which adds interior vertices: about M / 5 of them with the
// default quality bound. Prints one tab-separated row:
//   tet_vertices tets seconds_tet seconds_unfold seconds_metrics iterations
//   peak_rss_mb peak_rss_tetgen_mb E_str_exact E_geo_sources
// --analyze_only stops after the symbolic analysis of the global matrix and prints
//   tet_vertices tets seconds_tet seconds_analyze factor_nonzeros factor_gflops peak_rss_mb
#include <glog/logging.h>
#include <sys/resource.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/unfold_surface.h"
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

int run(int argc, char** argv) {
  std::string input;
  int resolution = 0;
  double divisions = 0;
  bool analyze_only = false;
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
    else
      throw UsageError("scale_bench: unknown argument '" + arg + "'");
  }
  if (input.empty() == (resolution == 0))
    throw UsageError("scale_bench: give exactly one of --input and --demo_resolution");
  const SurfaceMesh surface = input.empty()
                                  ? make_articulated_shape(ShapePose::preset(0), resolution)
                                  : read_surface_mesh(input);
  Options options;
  if (divisions > 0) options.tet.max_volume = enclosed_volume(surface) / divisions;
  if (analyze_only) {
    TetReport report;
    const TetMesh tets = tetrahedralize(surface, options.tet, &report);
    const auto start = std::chrono::steady_clock::now();
    const EdgeGraph graph = build_edge_graph(int(tets.V.rows()), tets.T);
    SparseLdlt ldlt;
    ldlt.analyze(graph_laplacian(graph));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d\t%d\t%.3f\t%.3f\t%.0f\t%.2f\t%.0f\n", int(tets.V.rows()), int(tets.T.rows()),
                report.seconds, seconds, ldlt.factor_nonzeros(), ldlt.factor_flops() / 1e9,
                peak_rss_mb(RUSAGE_SELF));
    return 0;
  }
  const UnfoldResult r = unfold_surface(surface, options);
  std::printf("%d\t%d\t%.3f\t%.3f\t%.3f\t%d\t%.0f\t%.0f\t%d\t%d\n", int(r.tets.V.rows()),
              int(r.tets.T.rows()), r.tet_report.seconds, r.seconds_unfold, r.metrics.seconds,
              r.cascade.iterations, peak_rss_mb(RUSAGE_SELF), peak_rss_mb(RUSAGE_CHILDREN),
              int(r.metrics.E_str_exact),
              r.metrics.E_geo_exact ? -1 : options.geodesic_metric.sources);
  return 0;
}

}  // namespace
}  // namespace unfold

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  FLAGS_minloglevel = 1;
  try {
    return unfold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scale_bench: %s\n", e.what());
    return 1;
  }
}
