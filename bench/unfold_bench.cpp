// Timings of the solver's parts on one tet mesh: numeric factorization, one
// forward/backward solve, one local step, one local-global iteration, the whole
// cascade, and the metrics. The mesh is $UNFOLD_BENCH_MESH, else TOSCA wolf0
// from ../shared/data, else the built-in demo shape.
//   build/bin/unfold_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <glog/logging.h>

#include <cstdio>
#include <cstdlib>

#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "metrics/geodesic_error.h"
#include "metrics/rigidity_error.h"
#include "metrics/stretch_error.h"
#include "shapes/articulated_shape.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

struct BenchMesh {
  std::string name;
  TetMesh tets;
  EdgeGraph graph;
  double beta = 0;
};

const BenchMesh& bench_mesh() {
  static const BenchMesh mesh = [] {
    BenchMesh m;
    const char* env = std::getenv("UNFOLD_BENCH_MESH");
    std::string path = env ? env : UNFOLD_SOURCE_DIR "/../shared/data/tosca/wolf0.off";
    SurfaceMesh surface;
    if (std::FILE* f = std::fopen(path.c_str(), "r")) {
      std::fclose(f);
      surface = read_surface_mesh(path);
      m.name = path;
    } else {
      surface = make_articulated_shape(ShapePose::preset(0));
      m.name = "demo shape, preset 0";
    }
    m.tets = tetrahedralize(surface, TetOptions{});
    m.graph = build_edge_graph(int(m.tets.V.rows()), m.tets.T);
    m.beta = 1.5 * m.graph.num_vertices / fiedler_value(graph_laplacian(m.graph));
    std::fprintf(stderr, "bench mesh: %s, %d tet vertices, %d edges\n", m.name.c_str(),
                 m.graph.num_vertices, m.graph.num_edges());
    return m;
  }();
  return mesh;
}

// A mid-cascade state: rotations after a few iterations, so the work is typical.
struct SolverState {
  LocalGlobalData data;
  Eigen::MatrixX3d Q;
  Rotations R;
  explicit SolverState(const BenchMesh& m) {
    local_global_precomputation(m.graph, m.tets.V, &data);
    local_global_set_beta(m.beta, &data);
    Q = m.tets.V;
    for (int k = 0; k < 3; ++k) {
      best_rotations(m.graph, m.tets.V, Q, &R);
      global_step(data, R, &Q);
    }
  }
};

void BM_SymbolicAnalysis(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  for (auto _ : state) {
    LocalGlobalData data;
    local_global_precomputation(m.graph, m.tets.V, &data);
    benchmark::DoNotOptimize(data.L.nonZeros());
  }
}
BENCHMARK(BM_SymbolicAnalysis)->Unit(benchmark::kMillisecond);

void BM_NumericFactorization(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  LocalGlobalData data;
  local_global_precomputation(m.graph, m.tets.V, &data);
  for (auto _ : state) local_global_set_beta(m.beta, &data);
}
BENCHMARK(BM_NumericFactorization)->Unit(benchmark::kMillisecond);

void BM_Solve(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m);
  for (auto _ : state) s.data.ldlt.solve(s.data.rhs, &s.Q);
}
BENCHMARK(BM_Solve)->Unit(benchmark::kMillisecond);

void BM_LocalStep(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m);
  for (auto _ : state) best_rotations(m.graph, m.tets.V, s.Q, &s.R);
}
BENCHMARK(BM_LocalStep)->Unit(benchmark::kMillisecond);

void BM_Iteration(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m);
  for (auto _ : state) {
    best_rotations(m.graph, m.tets.V, s.Q, &s.R);
    global_step(s.data, s.R, &s.Q);
  }
}
BENCHMARK(BM_Iteration)->Unit(benchmark::kMillisecond);

void BM_Cascade(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  CascadeOptions options;
  options.beta = m.beta;
  int iterations = 0;
  for (auto _ : state) iterations = run_cascade(m.graph, m.tets.V, options).iterations;
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_Cascade)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace unfold

int main(int argc, char** argv) {
  FLAGS_minloglevel = 1;  // the cascade's INFO lines would drown the table
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
