#include "stages/setup_cascade.h"

#include <glog/logging.h>

#include <chrono>
#include <tuple>
#include <utility>

#include "core/seconds_since.h"
#include "mesh/lumped_masses.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"

namespace unfold {
namespace {

// stretch.masses: lumped: the domain's lumped masses (tet volumes; the surface's
// areas when mesh has no tets) to stretch.mass_power, scaled to mean 1 so that
// M = n and the energy is bounded for beta > n / lambda_2 - 1 with lambda_2 that
// of L x = lambda M x (docs/method.md); uniform: none.
Eigen::VectorXd stretch_masses(const TetMesh& mesh, const SurfaceMesh& surface,
                               const EnergyOptions& options, const Eigen::VectorXd& given) {
  if (options.stretch_masses != "lumped") return {};
  const Eigen::VectorXd m =
      stretch_mass_shares(given.size() > 0    ? given
                          : mesh.T.rows() > 0 ? lumped_masses(mesh.V, mesh.T)
                                              : lumped_masses(mesh.V, triangulate_faces(surface)),
                          options);
  return m * (double(m.size()) / m.sum());
}

// From this many vertices linear_solver.method: auto builds the AMG hierarchy
// while it decides: every volume-filled mesh this large goes iterative, and
// of the shared meshes (all direct up to centaur's 17k) only cat0/cat1 (33k)
// reach it, both iterative (docs/performance.md). A surface alone (no tets)
// factors far more cheaply (david0's 52k vertices: 0.09 GFlop, auto's default
// bound 0.3), so from kSpeculativeAmgSurfaceVertices on: no hierarchy built
// only to be dropped, on the core the anchor unit's lambda_2 runs on.
constexpr int kSpeculativeAmgVertices = 20000;
constexpr int kSpeculativeAmgSurfaceVertices = 100000;

}  // namespace

CascadeSetup setup_cascade(const EdgeGraph& graph, const TetMesh& mesh, const SurfaceMesh& surface,
                           const CascadeSetupOptions& options,
                           const std::vector<double>& arap_factors,
                           const Eigen::VectorXd& given_masses, const EarlierSetup* earlier) {
  CascadeSetup setup;
  const Eigen::VectorXd masses = stretch_masses(mesh, surface, options.energy, given_masses);
  setup.problem = std::make_unique<UnfoldProblem>(make_unfold_problem(
      mesh, graph, options.energy, masses, arap_factors, earlier ? earlier->clusters : nullptr));
  const int n = graph.num_vertices;
  // The solver is decided once here (it needs a symbolic analysis), for
  // lambda_2 and the backend alike; the iterative one's AMG hierarchy serves both.
  const Eigen::SparseMatrix<double> L = beta_laplacian(*setup.problem);
  setup.backend_options = options.backend;
  LinearSolverOptions& solver = setup.backend_options.linear_solver;
  // The AMG hierarchy, and the seconds its build took.
  const auto build_amg = [&L] {
    const auto build_start = std::chrono::steady_clock::now();
    auto amg = std::make_shared<AmgData>();
    amg_precomputation(L, AmgOptions{}, amg.get());
    return std::make_pair(std::move(amg), seconds_since(build_start));
  };
  // auto's symbolic analysis and the AMG setup each run on one thread: from
  // kSpeculativeAmgVertices on, where auto nearly always goes iterative, the
  // hierarchy is built on the other core meanwhile (dropped if it goes direct).
  std::future<std::pair<std::shared_ptr<AmgData>, double>> speculative_amg;
  if (solver.method == "auto" &&
      n >= (mesh.T.rows() > 0 ? kSpeculativeAmgVertices : kSpeculativeAmgSurfaceVertices))
    speculative_amg = std::async(std::launch::async, build_amg);
  solver.method = use_iterative_solver(solver, L) ? "iterative" : "direct";
  if (solver.method == "iterative") {
    std::tie(setup.amg, setup.seconds_amg) =
        speculative_amg.valid() ? speculative_amg.get() : build_amg();
    setup.amg_levels = int(setup.amg->levels.size());
    setup.lambda2 = fiedler_value(L, *setup.amg, masses);
  } else {
    // With the direct solver, lambda_2's shift-invert Lanczos and the backend's
    // setup (the global matrix's symbolic analysis: beta only scales values) each
    // run on one thread: side by side (david0's surface: 0.13 s of 0.23 s hidden).
    setup.backend = std::async(std::launch::async,
                               [problem = setup.problem.get(), backend = setup.backend_options] {
                                 return make_backend(backend, *problem, nullptr);
                               });
    FiedlerPair fiedler =
        fiedler_pair(L, masses, earlier ? earlier->fiedler_vector : Eigen::VectorXd());
    setup.lambda2 = fiedler.value;
    setup.fiedler_vector = std::move(fiedler.vector);
  }
  setup.beta = starting_beta(options.beta_mode, options.beta_value, options.raise_beta_to_bound, n,
                             setup.lambda2, options.energy.stretch_weight);
  const double bound = n / setup.lambda2;
  if (setup.beta.raised) {
    setup.warnings.push_back(
        "beta " + std::to_string(setup.beta.requested) +
        " is below the bound stretch.weight (n/lambda_2 - 1) = " +
        std::to_string(beta_bound(n, setup.lambda2, options.energy.stretch_weight)) +
        ": raised to " + std::to_string(setup.beta.start));
    LOG(WARNING) << setup.warnings.back();
  }
  LOG(INFO) << "n = " << n << ", edges = " << graph.num_edges() << ", lambda_2 = " << setup.lambda2
            << ", n/lambda_2 = " << bound << ", starting beta = " << setup.beta.start << ", method "
            << options.backend.method;
  return setup;
}

}  // namespace unfold
