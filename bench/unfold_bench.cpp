// Timings of the solver's parts on one tet mesh: symbolic analysis, numeric
// factorization and one forward/backward solve for each sparse LDL^T backend,
// the AMG hierarchy, one V-cycle and one CG global step of the iterative
// solver, lambda_2 both ways, one local step, one global step, one
// local-global iteration and the whole cascade with either linear solver, the
// per-iteration checks (energy, edge ratio), the metrics, and the robust
// route's winding numbers at the Delaunay tets' centroids. The mesh is
// $UNFOLD_BENCH_MESH, else TOSCA wolf0 from ../shared/data, else the built-in
// demo shape; tetrahedralized with the default options and TetGen's volume
// bound $UNFOLD_BENCH_MAX_VOLUME if set. Direct-solver benchmarks are skipped
// above 60,000 vertices (one factorization takes minutes there).
//   build/bin/unfold_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <glog/logging.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "energies/quadratic_term.h"
#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/sort_interior_vertices.h"
#include "metrics/edge_ratio.h"
#include "metrics/geodesic_error.h"
#include "metrics/rigidity_error.h"
#include "metrics/stretch_error.h"
#include "shapes/articulated_shape.h"
#include "solvers/anderson_acceleration.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "solvers/sparse_ldlt.h"
#include "solvers/unfold_problem.h"
#include "tetra/delaunay_tets.h"
#include "tetra/fast_winding_number.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

constexpr int kDirectLimit = 60000;

struct BenchMesh {
  std::string name;
  SurfaceMesh surface;
  TetMesh tets;
  UnfoldProblem problem;
  std::shared_ptr<AmgData> amg;  ///< of the beta Laplacian
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
    TetOptions tet_options;
    if (const char* volume = std::getenv("UNFOLD_BENCH_MAX_VOLUME"))
      tet_options.max_volume = std::atof(volume);
    m.tets = tetrahedralize(surface, tet_options);
    m.surface = surface;
    sort_interior_vertices(&m.tets);  // as the pipeline does
    m.problem = make_unfold_problem(m.tets, build_edge_graph(int(m.tets.V.rows()), m.tets.T),
                                    EnergyOptions{});
    const Eigen::SparseMatrix<double> L = beta_laplacian(m.problem);
    m.amg = std::make_shared<AmgData>();
    amg_precomputation(L, AmgOptions{}, m.amg.get());
    m.beta = 1.5 * m.problem.graph->num_vertices / fiedler_value(L, *m.amg);
    std::fprintf(stderr, "bench mesh: %s, %d tet vertices, %d edges\n", m.name.c_str(),
                 m.problem.graph->num_vertices, m.problem.graph->num_edges());
    return m;
  }();
  return mesh;
}

// Arguments of the solver benchmarks: 0 direct, 1 iterative linear solver.
LinearSolverOptions solver_arg(const benchmark::State& state) {
  LinearSolverOptions options;
  options.method = state.range(0) == 0 ? "direct" : "iterative";
  return options;
}

// Skips direct-solver benchmarks on meshes where one factorization takes minutes.
bool skip_direct(benchmark::State& state, bool direct) {
  if (!direct || bench_mesh().problem.graph->num_vertices <= kDirectLimit) return false;
  state.SkipWithError("direct solver skipped above 60000 vertices");
  return true;
}

// A mid-cascade state: rotations after a few iterations, so the work is typical.
struct SolverState {
  LocalGlobalData data;
  Eigen::MatrixX3d Q;
  Rotations R;
  std::vector<Eigen::Matrix3d> covariances;
  SolverState(const BenchMesh& m, const LinearSolverOptions& options) {
    local_global_precomputation(m.problem, &data, options, m.amg);
    local_global_set_beta(m.beta, &data);
    Q = m.tets.V;
    for (int k = 0; k < 3; ++k) {
      fit_rotations(m.problem, Q, m.beta, &R, &covariances);
      global_step(data, R, &Q);
    }
  }
};

// Backends of the sparse LDL^T, compared on (beta+1) L - n I (argument: 0 Eigen, 1 CHOLMOD).
SparseLdlt::Backend backend_arg(const benchmark::State& state) {
  return state.range(0) == 0 ? SparseLdlt::Backend::kEigen : SparseLdlt::Backend::kCholmod;
}

Eigen::SparseMatrix<double> global_matrix(const BenchMesh& m) {
  Eigen::SparseMatrix<double> A = (m.beta + 1.0) * graph_laplacian(*m.problem.graph);
  A.diagonal().array() -= double(m.problem.graph->num_vertices);
  return A;
}

void BM_SymbolicAnalysis(benchmark::State& state) {
  if (skip_direct(state, true)) return;
  const Eigen::SparseMatrix<double> A = global_matrix(bench_mesh());
  for (auto _ : state) {
    SparseLdlt ldlt(backend_arg(state));
    ldlt.analyze(A);
  }
}
BENCHMARK(BM_SymbolicAnalysis)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_NumericFactorization(benchmark::State& state) {
  if (skip_direct(state, true)) return;
  const Eigen::SparseMatrix<double> A = global_matrix(bench_mesh());
  SparseLdlt ldlt(backend_arg(state));
  ldlt.analyze(A);
  for (auto _ : state) ldlt.factorize(A);
  state.counters["negative_pivots"] = ldlt.negative_pivots();
}
BENCHMARK(BM_NumericFactorization)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Solve(benchmark::State& state) {
  if (skip_direct(state, true)) return;
  const BenchMesh& m = bench_mesh();
  const Eigen::SparseMatrix<double> A = global_matrix(m);
  SparseLdlt ldlt(backend_arg(state));
  ldlt.analyze(A);
  ldlt.factorize(A);
  SolverState s(m, LinearSolverOptions{"direct"});
  Eigen::MatrixX3d x;
  for (auto _ : state) ldlt.solve(s.data.rhs, &x);
}
BENCHMARK(BM_Solve)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_AmgSetup(benchmark::State& state) {
  const Eigen::SparseMatrix<double> L = beta_laplacian(bench_mesh().problem);
  AmgData amg;
  for (auto _ : state) amg_precomputation(L, AmgOptions{}, &amg);
  state.counters["levels"] = double(amg.levels.size());
  state.counters["operator_complexity"] = amg.operator_complexity;
}
BENCHMARK(BM_AmgSetup)->Unit(benchmark::kMillisecond);

void BM_VCycle(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m, LinearSolverOptions{"iterative"});
  RowMatrixX3d x;
  const RowMatrixX3d b = s.data.rhs;
  for (auto _ : state) amg_vcycle(*s.data.amg, b, &x);
}
BENCHMARK(BM_VCycle)->Unit(benchmark::kMillisecond);

void BM_FiedlerValue(benchmark::State& state) {
  if (skip_direct(state, state.range(0) == 0)) return;
  const BenchMesh& m = bench_mesh();
  const Eigen::SparseMatrix<double> L = beta_laplacian(m.problem);
  double lambda2 = 0;
  for (auto _ : state) lambda2 = state.range(0) == 0 ? fiedler_value(L) : fiedler_value(L, *m.amg);
  state.counters["lambda2"] = lambda2;
}
BENCHMARK(BM_FiedlerValue)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_LocalStep(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m, LinearSolverOptions{});
  for (auto _ : state) fit_rotations(m.problem, s.Q, m.beta, &s.R, &s.covariances);
}
BENCHMARK(BM_LocalStep)->Unit(benchmark::kMillisecond);

// ARAP's quadratic form by its hand-written closed forms (0) and as derived
// from its residuals (1): the fast paths stay only while they are faster
// (docs/method.md). B(R) is needed every global step, H once per mesh.
const QuadraticTerm& arap_term(const BenchMesh& m) {
  for (const auto& term : m.problem.terms)
    if (term->name() == "arap") return dynamic_cast<const QuadraticTerm&>(*term);
  throw std::logic_error("no arap term");
}

void BM_ArapLinear(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  const QuadraticTerm& arap = arap_term(m);
  SolverState s(m, LinearSolverOptions{});
  Eigen::MatrixX3d B(m.problem.num_vertices(), 3);
  for (auto _ : state) {
    B.setZero();
    if (state.range(0) == 0)
      arap.add_linear(s.R, 1.0, &B);
    else
      arap.add_derived_linear(s.R, 1.0, &B);
    benchmark::DoNotOptimize(B.data());
  }
}
BENCHMARK(BM_ArapLinear)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_ArapHessian(benchmark::State& state) {
  const QuadraticTerm& arap = arap_term(bench_mesh());
  std::vector<Eigen::Triplet<double>> triplets;
  for (auto _ : state) {
    triplets.clear();
    if (state.range(0) == 0)
      arap.add_hessian(1.0, &triplets);
    else
      arap.add_derived_hessian(1.0, &triplets);
    benchmark::DoNotOptimize(triplets.data());
  }
}
BENCHMARK(BM_ArapHessian)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The iterative global step starts from the positions it replaces (warm
// start), so it is timed on a copy of one fixed mid-cascade state.
void BM_GlobalStep(benchmark::State& state) {
  if (skip_direct(state, state.range(0) == 0)) return;
  const BenchMesh& m = bench_mesh();
  SolverState s(m, solver_arg(state));
  Eigen::MatrixX3d Q;
  for (auto _ : state) {
    Q = s.Q;
    global_step(s.data, s.R, &Q);
  }
  if (s.data.iterative)
    state.counters["cg_iterations"] = double(s.data.cg_stats.iterations) / s.data.cg_stats.solves;
}
BENCHMARK(BM_GlobalStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Iteration(benchmark::State& state) {
  if (skip_direct(state, state.range(0) == 0)) return;
  const BenchMesh& m = bench_mesh();
  SolverState s(m, solver_arg(state));
  const Eigen::MatrixX3d start = s.Q;
  for (auto _ : state) {
    s.Q = start;
    fit_rotations(m.problem, s.Q, m.beta, &s.R, &s.covariances);
    global_step(s.data, s.R, &s.Q);
  }
}
BENCHMARK(BM_Iteration)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// What Algorithm 1 computes after each iteration to decide whether to go on:
// the energy (from the global step's quadratic form) and the edge ratio.
void BM_IterationChecks(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m, LinearSolverOptions{});
  for (auto _ : state) {
    benchmark::DoNotOptimize(energy_after_global_step(s.data, s.R, s.Q));
    benchmark::DoNotOptimize(edge_ratio(*m.problem.graph, m.tets.V, s.Q));
  }
}

// The energy as a sweep over every term's cells, for comparison.
void BM_EnergySweep(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  SolverState s(m, LinearSolverOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(total_energy(m.problem, s.Q, s.R, m.beta));
}
BENCHMARK(BM_EnergySweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IterationChecks)->Unit(benchmark::kMillisecond);

void BM_Cascade(benchmark::State& state) {
  if (skip_direct(state, state.range(0) == 0)) return;
  const BenchMesh& m = bench_mesh();
  CascadeOptions options;
  options.beta = m.beta;
  int iterations = 0;
  for (auto _ : state) {
    LocalGlobalBackend backend(m.problem, solver_arg(state), m.amg);
    iterations = run_cascade(m.problem, backend, options).iterations;
  }
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_Cascade)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The metrics on the bench mesh's rest pose against a rotated, scaled copy
// (the cost does not depend on the shape), with the default options.
Eigen::MatrixX3d moved(const BenchMesh& m) {
  return 1.1 * m.tets.V * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// One Anderson step (window 5) on the unknowns of a 55k-vertex tet mesh (david0's
// unfolded shape): the cascades and the anchored steps take one per iteration.
void BM_AndersonStep(benchmark::State& state) {
  const Eigen::Index n = 3 * 55134;
  const Eigen::VectorXd target = Eigen::VectorXd::Random(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), g(n), out(n);
  AndersonAcceleration anderson(5);
  double t = 0;
  for (auto _ : state) {
    t += 1;  // a slowly converging, never repeating map
    g = x + (0.1 + 0.05 * std::sin(t)) * (target - x);
    anderson.next(x, g, out);
    x.swap(out);
  }
}
BENCHMARK(BM_AndersonStep)->Unit(benchmark::kMillisecond);

void BM_RigidityError(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  const Eigen::MatrixX3d Q = moved(m);
  for (auto _ : state) benchmark::DoNotOptimize(rigidity_error(*m.problem.graph, m.tets.V, Q).mean);
}
BENCHMARK(BM_RigidityError)->Unit(benchmark::kMillisecond);

void BM_StretchError(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  const Eigen::MatrixX3d Q = moved(m);
  StretchError e;
  for (auto _ : state) e = stretch_error(m.tets.V, Q);
  state.counters["exact"] = e.exact;
}
BENCHMARK(BM_StretchError)->Unit(benchmark::kMillisecond);

void BM_GeodesicError(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  const Eigen::MatrixX3d Q = moved(m);
  GeodesicError e;
  for (auto _ : state) e = geodesic_error(*m.problem.graph, m.tets.V, Q);
  state.counters["sources"] = e.sources_used;
}
BENCHMARK(BM_GeodesicError)->Unit(benchmark::kMillisecond);

// The robust route's carve: the winding numbers at the centroids of the
// Delaunay tets of the surface's vertices (inside, outside and slivers on the
// surface, as the carve meets them); arg 0: classify (the carve's), 1: solve
// (the accurate pass).
void BM_WindingNumbers(benchmark::State& state) {
  const BenchMesh& m = bench_mesh();
  const FastWindingNumberTree tree =
      fast_winding_number_precomputation(m.surface.V, triangulate_faces(m.surface));
  const Eigen::MatrixX4i T = delaunay_tets(m.surface.V);
  Eigen::MatrixX3d centroids(T.rows(), 3);
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    centroids.row(t) = (m.surface.V.row(T(t, 0)) + m.surface.V.row(T(t, 1)) +
                        m.surface.V.row(T(t, 2)) + m.surface.V.row(T(t, 3))) /
                       4;
  Eigen::VectorXd w;
  for (auto _ : state)
    w = state.range(0) == 0 ? fast_winding_number_classify(tree, centroids)
                            : fast_winding_number_solve(tree, centroids);
  state.counters["queries"] = double(centroids.rows());
  state.counters["inside"] = double((w.array() > 0.5).count());
}
BENCHMARK(BM_WindingNumbers)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace unfold

int main(int argc, char** argv) {
  FLAGS_minloglevel = 1;  // the cascade's INFO lines would drown the table
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
