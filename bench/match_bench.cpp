// Timings of unfold_match's parts on one pair, after the unfolding (what the
// time per pair counts): each shape's preparation (Laplace-Beltrami basis and
// curvature descriptor, once per shape in a batch), the rigid alignment of the
// canonical forms with every candidate placement, one ZoomOut on the samples,
// the pointwise map of every vertex, and the whole match_shapes. The pair is
// $UNFOLD_BENCH_SOURCE and $UNFOLD_BENCH_TARGET (surfaces; their canonical
// forms computed with the default config), else FAUST tr_reg_010 and tr_reg_031
// from ../shared/data/faust_people, else two poses of the built-in demo shape.
//   build/bin/match_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <glog/logging.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "config/options.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/match_surfaces.h"
#include "shapes/articulated_shape.h"

namespace unfold {
namespace {

struct BenchPair {
  MatchShape source, target;
  MatchOptions options;
};

SurfaceMesh bench_surface(const char* variable, const std::string& shared, int pose) {
  const char* env = std::getenv(variable);
  const std::string path = env ? env : UNFOLD_SOURCE_DIR "/../shared/data/faust_people/" + shared;
  if (std::FILE* f = std::fopen(path.c_str(), "r")) {
    std::fclose(f);
    std::printf("%s: %s\n", variable, path.c_str());
    return read_surface_mesh(path);
  }
  std::printf("%s: the demo shape, preset %d\n", variable, pose);
  return make_articulated_shape(ShapePose::preset(pose));
}

const BenchPair& bench_pair() {
  static const BenchPair pair = [] {
    BenchPair p;
    Options options;
    p.options = options.match;
    p.source =
        unfold_for_matching(bench_surface("UNFOLD_BENCH_SOURCE", "tr_reg_010.off", 0), options);
    p.target =
        unfold_for_matching(bench_surface("UNFOLD_BENCH_TARGET", "tr_reg_031.off", 1), options);
    return p;
  }();
  return pair;
}

void BM_PrepareShape(benchmark::State& state) {
  const BenchPair& p = bench_pair();
  for (auto _ : state)
    benchmark::DoNotOptimize(
        prepare_match_shape(p.source.V, p.source.canonical, p.source.F, p.options));
  state.counters["vertices"] = double(p.source.V.rows());
}
BENCHMARK(BM_PrepareShape)->Unit(benchmark::kMillisecond);

void BM_AlignForms(benchmark::State& state) {
  const BenchPair& p = bench_pair();
  for (auto _ : state)
    benchmark::DoNotOptimize(align_canonical_forms(
        p.source.canonical, p.source.F, p.target.canonical, p.target.F, p.options.alignment));
}
BENCHMARK(BM_AlignForms)->Unit(benchmark::kMillisecond);

void BM_ZoomOutOnSamples(benchmark::State& state) {
  const BenchPair& p = bench_pair();
  ZoomOutOptions zoom = p.options.zoomout;
  zoom.final_size = p.options.spectral_size;
  const ShapeMatch m = match_shapes(p.source, p.target, p.options);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        zoomout_functional_map(p.source.basis, p.target.basis, m.oriented, zoom));
}
BENCHMARK(BM_ZoomOutOnSamples)->Unit(benchmark::kMillisecond);

void BM_PointwiseMapEveryVertex(benchmark::State& state) {
  const BenchPair& p = bench_pair();
  ZoomOutOptions zoom = p.options.zoomout;
  zoom.final_size = p.options.spectral_size;
  const Eigen::MatrixXd C = zoomout_functional_map(
      p.source.basis, p.target.basis, match_shapes(p.source, p.target, p.options).oriented, zoom);
  for (auto _ : state) benchmark::DoNotOptimize(pointwise_map(p.source.basis, p.target.basis, C));
}
BENCHMARK(BM_PointwiseMapEveryVertex)->Unit(benchmark::kMillisecond);

void BM_MatchShapes(benchmark::State& state) {
  const BenchPair& p = bench_pair();
  for (auto _ : state) {
    const ShapeMatch m = match_shapes(p.source, p.target, p.options);
    state.counters["align_s"] = m.seconds_align;
    state.counters["refine_s"] = m.seconds_refine;
  }
}
BENCHMARK(BM_MatchShapes)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace unfold

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
