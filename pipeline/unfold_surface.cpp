#include "pipeline/unfold_surface.h"

#include <glog/logging.h>
#include <omp.h>

#include <chrono>
#include <future>
#include <limits>
#include <tuple>
#include <utility>

#include "core/errors.h"
#include "core/fork_safety.h"
#include "core/parallel.h"
#include "core/seconds_since.h"
#include "energies/soft_joint_factors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/edge_graph.h"
#include "mesh/lumped_masses.h"
#include "mesh/simplify_surface_mesh.h"
#include "mesh/sort_interior_vertices.h"
#include "mesh/tet_and_surface_edge_graph.h"
#include "mesh/tet_volumes.h"
#include "metrics/edge_ratio.h"
#include "metrics/geodesic_error.h"
#include "metrics/rigidity_error.h"
#include "metrics/stretch_error.h"
#include "pipeline/scf_unfold.h"
#include "pipeline/unfold_components.h"
#include "solvers/arap_solve.h"
#include "solvers/beta_schedule.h"
#include "solvers/cascade.h"
#include "solvers/contact_bridges.h"
#include "solvers/fiedler_value.h"
#include "solvers/integrate_rotation_field.h"
#include "solvers/local_global.h"
#include "solvers/lsmds.h"
#include "solvers/make_backend.h"
#include "solvers/tetrahedralize_unfolded.h"
#include "tetra/intersecting_faces.h"

namespace unfold {
namespace {

// The solver divides by rest edge lengths and needs one connected graph.
void check_tet_graph(const EdgeGraph& graph, const Eigen::MatrixX3d& V) {
  const int components = connected_components(graph);
  if (components != 1)
    throw NumericalError("the tet mesh's edge graph has " + std::to_string(components) +
                         " connected components; unfolding needs one");
  for (int e = 0; e < graph.num_edges(); ++e)
    if ((V.row(graph.edges(e, 0)) - V.row(graph.edges(e, 1))).norm() == 0)
      throw NumericalError("tet mesh edge " + std::to_string(graph.edges(e, 0)) + "-" +
                           std::to_string(graph.edges(e, 1)) + " has zero length");
}

// A TetMesh without tets: the surface's vertices alone.
TetMesh surface_only(const SurfaceMesh& surface) {
  TetMesh mesh;
  mesh.V = surface.V;
  mesh.T.resize(0, 4);
  mesh.num_surface_vertices = int(surface.V.rows());
  return mesh;
}

// The tet mesh of a closed surface; when none can be made (open surface,
// tetrahedralization failed) and the options allow it, the surface alone: a
// TetMesh without tets, whose edge graph is then the triangles'.
TetMesh tetrahedralize_or_fall_back(const SurfaceMesh& surface, bool open, const Options& options,
                                    TetReport* report, std::vector<std::string>* warnings,
                                    int known_intersections = -1) {
  std::string reason = "the surface is open";
  if (!open) {
    try {
      return tetrahedralize(surface, options.tet, report, known_intersections);
    } catch (const NumericalError& e) {
      if (!options.fallback_surface_graph)
        throw NumericalError(std::string(e.what()) +
                             " (tetrahedralize.fallback_surface_graph: true unfolds the surface "
                             "edge graph instead)");
      reason = e.what();
    }
  }
  warnings->push_back("no tet mesh (" + reason + "): unfolding on the surface edge graph");
  LOG(WARNING) << warnings->back();
  *report = TetReport{};
  report->route = "surface_graph";
  return surface_only(surface);
}

// stretch.masses: lumped: the domain's lumped masses (tet volumes; the surface's
// areas when mesh has no tets), scaled to mean 1 so that M = n and the energy
// is bounded for beta > n / lambda_2 - 1 with lambda_2 that of L x = lambda M x
// (docs/method.md); uniform: none.
Eigen::VectorXd stretch_masses(const TetMesh& mesh, const SurfaceMesh& surface,
                               const EnergyOptions& options) {
  if (options.stretch_masses != "lumped") return {};
  Eigen::VectorXd m = mesh.T.rows() > 0 ? lumped_masses(mesh.V, mesh.T)
                                        : lumped_masses(mesh.V, triangulate_faces(surface));
  return m * (double(m.size()) / m.sum());
}

// From this many vertices linear_solver.method: auto builds the AMG hierarchy
// while it decides: every volume-filled mesh this large goes iterative, and
// of the shared meshes (all direct up to centaur's 17k) only cat0/cat1 (33k)
// reach it, both iterative (docs/performance.md).
constexpr int kSpeculativeAmgVertices = 20000;

// lambda_2, beta and the cascade on the vertices and edges of `mesh`, the ARAP
// weights times arap_factors (none when empty), from `warm` (null: the rest
// positions). Times add to out's. Returns the linear solver it used for lambda_2
// and the global steps: direct or iterative (options.linear_solver.method
// decided, for auto).
std::string cascade_once(const EdgeGraph& graph, const TetMesh& mesh, const Options& options,
                         const Eigen::VectorXd& masses, const std::vector<double>& arap_factors,
                         const Eigen::MatrixX3d* warm, UnfoldResult* out) {
  UnfoldResult& result = *out;
  const auto start = std::chrono::steady_clock::now();
  const UnfoldProblem problem =
      make_unfold_problem(mesh, graph, options.energy, masses, arap_factors);
  const int n = graph.num_vertices;
  // The solver is decided once here (it needs a symbolic analysis), for
  // lambda_2 and the backend alike; the iterative one's AMG hierarchy serves both.
  const Eigen::SparseMatrix<double> L = beta_laplacian(problem);
  LinearSolverOptions solver = options.linear_solver;
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
  if (solver.method == "auto" && n >= kSpeculativeAmgVertices)
    speculative_amg = std::async(std::launch::async, build_amg);
  solver.method = use_iterative_solver(solver, L) ? "iterative" : "direct";
  result.linear_solver = solver.method;
  std::shared_ptr<AmgData> amg;
  const auto build_backend = [&] {
    return make_backend({options.method, solver, options.ceres}, problem, amg);
  };
  // With the direct solver, lambda_2's shift-invert Lanczos and the backend's
  // setup (the global matrix's symbolic analysis: beta only scales values) each
  // run on one thread: side by side (david0's surface: 0.13 s of 0.23 s hidden).
  std::future<std::unique_ptr<CascadeBackend>> direct_backend;
  if (result.linear_solver == "iterative") {
    double seconds_amg = 0;
    std::tie(amg, seconds_amg) = speculative_amg.valid() ? speculative_amg.get() : build_amg();
    result.seconds_amg += seconds_amg;
    result.amg_levels = int(amg->levels.size());
    result.lambda2 = fiedler_value(L, *amg, masses);
  } else {
    direct_backend = std::async(std::launch::async, build_backend);
    result.lambda2 = fiedler_value(L, masses);
  }
  const BetaStart beta = starting_beta(options.beta_mode, options.beta_value,
                                       options.raise_beta_to_bound, n, result.lambda2);
  result.beta_requested = beta.requested;
  result.beta_start = beta.start;
  result.beta_raised = beta.raised;
  const double bound = n / result.lambda2;
  if (beta.raised) {
    result.warnings.push_back("beta " + std::to_string(result.beta_requested) +
                              " is below the bound n/lambda_2 - 1 = " + std::to_string(bound - 1) +
                              ": raised to " + std::to_string(result.beta_start));
    LOG(WARNING) << result.warnings.back();
  }
  LOG(INFO) << "n = " << n << ", edges = " << graph.num_edges() << ", lambda_2 = " << result.lambda2
            << ", n/lambda_2 = " << bound << ", starting beta = " << result.beta_start
            << ", method " << options.method;
  CascadeOptions cascade = options.cascade;
  cascade.beta = result.beta_start;
  result.seconds_lambda2 += seconds_since(start);
  const auto cascade_start = std::chrono::steady_clock::now();
  const std::unique_ptr<CascadeBackend> backend =
      direct_backend.valid() ? direct_backend.get() : build_backend();
  result.cascade = run_cascade(problem, *backend, cascade, warm);
  result.seconds_cascade += seconds_since(cascade_start);
  const auto* local_global = dynamic_cast<const LocalGlobalBackend*>(backend.get());
  if (!local_global) {
    result.linear_solver = "ceres";
    return solver.method;
  }
  result.cg = local_global->data().cg_stats;
  if (result.cg.unconverged_solves > 0)
    result.warnings.push_back(
        std::to_string(result.cg.unconverged_solves) + " of " + std::to_string(result.cg.solves) +
        " global steps stopped at linear_solver.cg_max_iterations (worst relative residual " +
        std::to_string(result.cg.worst_relative_residual) + ")");
  return solver.method;
}

// The paper's method and the energy-term baselines: lambda_2, beta, the cascade,
// on the vertices and edges of `mesh`. With soften.scale > 0 and an ARAP term,
// solved twice: the second time with the first solution's joints softened
// (energies/soft_joint_factors.h), from that solution.
void solve_cascade(const EdgeGraph& graph, const TetMesh& mesh, const Options& options,
                   UnfoldResult* out) {
  const Eigen::VectorXd masses = stretch_masses(mesh, out->surface, options.energy);
  if (!(options.soften.scale > 0 && options.energy.arap_weight > 0)) {
    cascade_once(graph, mesh, options, masses, {}, nullptr, out);
    return;
  }
  // The first solve converged as far as the second: stopped earlier (100 times
  // cascade.epsilon), its joints differ enough to move wolf's mean pose ratio
  // from 0.19 to 0.28 (docs/method.md, soft joints).
  Options softened = options;
  // The reweighted matrices have the first solve's pattern, so its solver
  // serves them: no second symbolic analysis, and no speculative AMG hierarchy
  // built only to be dropped.
  softened.linear_solver.method = cascade_once(graph, mesh, options, masses, {}, nullptr, out);
  const Eigen::MatrixX3d solved = out->cascade.positions;
  const int first_iterations = out->cascade.iterations;
  cascade_once(graph, mesh, softened, masses,
               soft_joint_factors(graph, mesh.V, solved, options.soften), &solved, out);
  LOG(INFO) << "soft joints: " << first_iterations << " iterations, then "
            << out->cascade.iterations << " with the joints softened";
}

// domain: surface. The energy lives on the surface's vertices and triangle
// edges, whose rest state barely changes with the pose (a bent knee's skin keeps
// its lengths; its interior tets are bent); the interior then follows by ARAP
// on the tet edges (docs/method.md, pose invariance).
void solve_surface_cascade(const Options& options, UnfoldResult* out) {
  TetMesh surface;
  surface.V = out->surface.V;
  surface.num_surface_vertices = int(surface.V.rows());
  surface.T.resize(0, 4);
  const EdgeGraph surface_graph = build_edge_graph(
      surface.num_surface_vertices, Eigen::MatrixXi(triangulate_faces(out->surface)));
  check_tet_graph(surface_graph, surface.V);
  solve_cascade(surface_graph, surface, options, out);
}

// The surface solve's results into `out`: those of `solved` when it ran
// already (unfold_surface runs it while the input's tets are made), else solved here.
void surface_cascade(const Options& options, const UnfoldResult* solved, UnfoldResult* out) {
  if (!solved) return solve_surface_cascade(options, out);
  out->cascade = solved->cascade;
  out->lambda2 = solved->lambda2;
  out->beta_requested = solved->beta_requested;
  out->beta_start = solved->beta_start;
  out->beta_raised = solved->beta_raised;
  out->linear_solver = solved->linear_solver;
  out->amg_levels = solved->amg_levels;
  out->seconds_amg = solved->seconds_amg;
  out->cg = solved->cg;
  out->seconds_lambda2 = solved->seconds_lambda2;
  out->seconds_cascade = solved->seconds_cascade;
  out->warnings.insert(out->warnings.end(), solved->warnings.begin(), solved->warnings.end());
}

void solve_on_surface(const EdgeGraph& tet_graph, const Options& options,
                      const UnfoldResult* solved, UnfoldResult* out) {
  UnfoldResult& result = *out;
  surface_cascade(options, solved, out);
  const int num_surface = result.tets.num_surface_vertices;
  Eigen::MatrixX3d Q = result.tets.V.rowwise() - result.tets.V.colwise().mean();
  Q.topRows(num_surface) = result.cascade.positions;
  ArapSolveOptions place;
  place.num_fixed = num_surface;
  const auto interior_start = std::chrono::steady_clock::now();
  result.cascade.positions = arap_solve(tet_graph, result.tets.V, std::move(Q), place);
  result.seconds_interior = seconds_since(interior_start);
}

// The edges every stage after the tets are made solves on: the tets' (the
// triangles' without tets), joined with the surface's when `surface_weight` > 0
// (integrate.surface_edges, mesh/tet_and_surface_edge_graph.h); then
// `integrate_factors` gives the integration's weight factor of each edge:
// `surface_weight` on the surface's edges that no tet has, else 1. The
// metrics measure on the same edges: the paper's tets (TetGen's, conforming)
// have every surface edge too.
EdgeGraph solve_graph(const UnfoldResult& result, double surface_weight,
                      std::vector<double>* integrate_factors, std::vector<std::string>* warnings) {
  const TetMesh& tets = result.tets;
  integrate_factors->clear();
  if (tets.T.rows() == 0)
    return build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(triangulate_faces(result.surface)));
  if (!(surface_weight > 0)) return build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(tets.T));
  int zero_length = 0;
  std::vector<char> surface_only;
  EdgeGraph graph = tet_and_surface_edge_graph(tets.V, tets.T, triangulate_faces(result.surface),
                                               &surface_only, &zero_length);
  if (zero_length > 0) {
    warnings->push_back(std::to_string(zero_length) +
                        " tet edges join vertices that coincide in the input and share no "
                        "triangle (a contact): left out of the solve");
    LOG(WARNING) << warnings->back();
  }
  integrate_factors->resize(surface_only.size());
  for (size_t e = 0; e < surface_only.size(); ++e)
    (*integrate_factors)[e] = surface_only[e] ? surface_weight : 1.0;
  return graph;
}

// The integration's anchor unit (integrate_cascade_rotations).
double surface_lambda2(const SurfaceMesh& surface) {
  return fiedler_value(graph_laplacian(
      build_edge_graph(int(surface.V.rows()), Eigen::MatrixXi(triangulate_faces(surface)))));
}

// tetrahedralize.shape: unfolded. The surface solve S first, then the tet mesh
// of S, its interior put back into the input (solvers/tetrahedralize_unfolded.h):
// parts that touch in the input are joined by no tet. The result's tets become
// that mesh, and the cascade's positions S's own tet mesh; with `given_unfolded`
// (given tets and where they were made) those instead. With `integrates`,
// returns surface_lambda2 computed meanwhile, on one thread; else no future.
// It depends on the surface alone: below kMinParallelRows vertices the surface
// solve runs on one thread and it goes beside that (wolf0: out of the way of
// the carve's two threads); above, beside the tets' Delaunay, which runs in
// TetGen's process and leaves a core idle.
std::future<double> solve_on_unfolded_tets(const Options& options, const UnfoldResult* solved,
                                           bool integrates, UnfoldResult* out,
                                           const Eigen::MatrixX3d* given_unfolded = nullptr) {
  UnfoldResult& result = *out;
  std::future<double> lambda2;
  const auto start_lambda2 = [&] {
    if (integrates && kForkAlongsideThreads && !lambda2.valid())
      lambda2 =
          std::async(std::launch::async, [&result] { return surface_lambda2(result.surface); });
  };
  if (result.surface.V.rows() < kMinParallelRows) start_lambda2();
  surface_cascade(options, solved, out);
  start_lambda2();
  if (given_unfolded) {
    // Given tets made on an unfolded shape (an earlier run's): its surface is
    // this solve's, the interior where the tets were made.
    Eigen::MatrixX3d unfolded = *given_unfolded;
    unfolded.topRows(result.surface.V.rows()) = result.cascade.positions;
    result.cascade.positions = unfolded.rowwise() - unfolded.colwise().mean();
    result.unfolded_tet_positions = std::move(unfolded);
    return lambda2;
  }
  const auto start = std::chrono::steady_clock::now();
  // Route auto is robust for the unfolded shape: it may or may not intersect
  // itself somewhere, and one route for every pose keeps the poses' tets alike.
  TetOptions tet = options.tet;
  if (tet.route == "auto") tet.route = "robust";
  UnfoldedTetMesh unfolded =
      tetrahedralize_unfolded(result.surface, result.cascade.positions, tet,
                              integrates && options.integrate.surface_edges > 0);
  result.tets = std::move(unfolded.rest);
  result.tet_report = unfolded.report;
  result.tet_report.seconds = seconds_since(start);
  result.cascade.positions = unfolded.unfolded.rowwise() - unfolded.unfolded.colwise().mean();
  result.unfolded_tet_positions = std::move(unfolded.unfolded);
  LOG(INFO) << "tetrahedralized the unfolded shape (" << result.tet_report.route
            << "): " << result.tets.V.rows() << " vertices, " << result.tets.T.rows() << " tets in "
            << result.tet_report.seconds << " s; " << result.tet_report.dropped_inverted_tets
            << " inverted at rest dropped, " << result.tet_report.inverted_rest_tets
            << " kept to keep it connected";
  return lambda2;
}

// integrate: the cascade's rotation field integrated on the whole tet mesh
// (docs/method.md, pose invariance). The anchor's unit is lambda_2 of the
// surface's uniform graph Laplacian: it depends on the connectivity alone, so
// it is the same for every pose of a shape (the tet mesh's is not) and for
// every arap.weight and arap.weights (the cascade's lambda_2 is not):
// `lambda2` is surface_lambda2(result.surface).
void integrate_cascade_rotations(const EdgeGraph& graph, const std::vector<double>& edge_factors,
                                 const Options& options, double lambda2, UnfoldResult* out) {
  UnfoldResult& result = *out;
  CascadeResult& c = result.cascade;
  IntegrateTimes times;
  c.positions = integrate_rotation_field(graph, result.tets.V, c.positions, lambda2,
                                         options.integrate, &times, edge_factors);
  result.seconds_integration = times.integration;
  result.seconds_anchored = times.anchored;
  c.edge_ratio = edge_ratio(graph, result.tets.V, c.positions);
  c.reached_band = in_band(c.edge_ratio, options.cascade.edge_ratio_band);
}

// LSMDS has no cascade: one stage, iterations = Guttman transforms, energy =
// the stress (beta 0 in the history).
CascadeResult lsmds_cascade_result(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                   const LsmdsOptions& options) {
  CascadeResult c;
  const LsmdsResult lsmds_result =
      lsmds(graph, P, options, [&](int k, const Eigen::MatrixX3d& X, double stress) {
        c.history.push_back({k, 1, 0.0, stress, edge_ratio(graph, P, X)});
      });
  c.positions = lsmds_result.positions;
  c.iterations = lsmds_result.iterations;
  c.cascades = 1;
  c.final_energy = lsmds_result.stress.back();
  c.edge_ratio = edge_ratio(graph, P, c.positions);
  c.reached_band = true;  // no band applies
  return c;
}

// E_geo's rows of G depend on the rest shape alone. Where the solve runs on
// one thread (fewer than kMinParallelRows vertices; LSMDS excepted, which runs
// Dijkstras of its own in parallel), they are computed on the other core
// meanwhile, on one thread so that nothing waits on a shared core; the rows
// must fit in 32 MB. Otherwise no future: E_geo after the solve, in parallel.
// Why E_geo is left out though asked for (more tet vertices than
// metrics.geodesic_max_vertices), and how to get it; "" when it is computed.
std::string geodesic_skipped(const Options& options, int num_vertices) {
  const int limit = options.geodesic_max_vertices;
  if (!computes_metric(options, "E_geo") || limit == 0 || num_vertices <= limit) return "";
  return "E_geo left out above " + std::to_string(limit) + " tet vertices (here " +
         std::to_string(num_vertices) +
         "); --metrics E_rig,E_str,E_geo (or metrics.geodesic_max_vertices: 0) computes it";
}

std::future<GeodesicRows> start_geodesic_rows(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                              const Options& options) {
  const GeodesicErrorOptions& geo = options.geodesic_metric;
  const int n = graph.num_vertices;
  const double rows = n <= geo.exact_limit ? n : std::min(geo.sources, n);
  if (!computes_metric(options, "E_geo") || !geodesic_skipped(options, n).empty() ||
      options.method == "lsmds" || n < 2 || n >= kMinParallelRows ||
      rows * n * sizeof(double) > (32 << 20))
    return {};
  return std::async(std::launch::async, [&graph, &P, geo] {
    omp_set_num_threads(1);
    return geodesic_error_precomputation(graph, P, geo);
  });
}

// prepare_mesh up to the input's tets: checks, simplification, contact by
// intersecting faces. What the tets then need besides the surface.
struct PendingTets {
  bool open = false;
  int known_intersections = -1;
};

PreparedMesh prepare_surface(const SurfaceMesh& input, const Options& options,
                             PendingTets* pending) {
  validate_options(options);
  const auto start = std::chrono::steady_clock::now();
  PreparedMesh prepared;
  const SurfaceReport report = check_surface_mesh(input, true);
  // A tet mesh needs a closed surface. The robust route's winding number closes
  // small holes (cat0 has 76 boundary edges in 83,606); larger ones leave no
  // well-defined inside, and the conforming route needs none at all. The
  // surface graph may stand in when allowed.
  size_t num_sides = 0;
  for (const auto& f : input.faces) num_sides += f.size();
  const bool small_holes =
      options.tet.route != "conforming" && size_t(report.num_boundary_edges) * 200 <= num_sides;
  const bool open = report.num_boundary_edges > 0 && !small_holes;
  if (open && !options.fallback_surface_graph)
    throw InputError("the surface is open (" + std::to_string(report.num_boundary_edges) +
                     " boundary edges); unfold needs a closed surface (with the auto and robust "
                     "routes: at most 1% boundary edges; or tetrahedralize.fallback_surface_graph: "
                     "true)");
  prepared.warnings = report.warnings;
  for (const auto& w : report.warnings) LOG(WARNING) << w;

  if (options.target_vertices > 0 && options.target_vertices < input.V.rows()) {
    prepared.surface = simplify_surface_mesh(input, options.target_vertices);
    LOG(INFO) << "simplified " << input.V.rows() << " -> " << prepared.surface.V.rows()
              << " vertices";
    check_surface_mesh(prepared.surface);
  } else {
    prepared.surface = input;
  }

  // tetrahedralize.shape contact: parts of the surface that pass through each
  // other are contact before any tet is made, and the input's tets would only
  // be checked and dropped (every such shape of ../shared/data also has tets
  // bridging a contact, docs/method.md).
  // A route of conforming asks for TetGen's own tets of the input, whose
  // refusal of such a surface is then the answer.
  int known_intersections = -1;
  if (tets_from_unfolded_on_contact(options) && !open && options.tet.route != "conforming") {
    const auto contact_start = std::chrono::steady_clock::now();
    const auto pairs =
        intersecting_face_pairs(prepared.surface.V, triangulate_faces(prepared.surface));
    known_intersections = int(pairs.size());
    prepared.tet_report.contact_face_pairs =
        count_intersections_far_along_surface(prepared.surface, pairs, options.contact_geodesic);
    prepared.seconds_contact = seconds_since(contact_start);
    if (prepared.tet_report.contact_face_pairs > 0)
      LOG(INFO) << prepared.tet_report.contact_face_pairs << " of the surface's "
                << known_intersections
                << " intersecting face pairs are parts passing through each other: "
                   "tetrahedralizing the unfolded shape";
  }
  if ((tets_from_unfolded(options) || prepared.tet_report.contact_face_pairs > 0) && !open) {
    // made after the surface solve, by unfold_prepared
    prepared.tets = surface_only(prepared.surface);
    prepared.tets_deferred = true;
  }
  *pending = {open, known_intersections};
  prepared.seconds = seconds_since(start);
  return prepared;
}

// prepare_mesh's rest: the input's tets.
void make_input_tets(const Options& options, const PendingTets& pending, PreparedMesh* prepared) {
  const auto start = std::chrono::steady_clock::now();
  prepared->tets =
      tetrahedralize_or_fall_back(prepared->surface, pending.open, options, &prepared->tet_report,
                                  &prepared->warnings, pending.known_intersections);
  sort_interior_vertices(&prepared->tets);
  LOG(INFO) << "tetrahedralized (" << prepared->tet_report.route << "): " << prepared->tets.V.rows()
            << " vertices, " << prepared->tets.T.rows() << " tets in "
            << prepared->tet_report.seconds << " s";
  prepared->seconds += seconds_since(start);
}

UnfoldResult unfold_prepared(const PreparedMesh& prepared, const Options& options,
                             const UnfoldResult* solved);

}  // namespace

PreparedMesh prepare_mesh(const SurfaceMesh& input, const Options& options) {
  PendingTets pending;
  PreparedMesh prepared = prepare_surface(input, options, &pending);
  if (!prepared.tets_deferred) make_input_tets(options, pending, &prepared);
  return prepared;
}

UnfoldResult unfold_prepared(const PreparedMesh& prepared, const Options& options) {
  return unfold_prepared(prepared, options, nullptr);
}

namespace {

// With `solved`, the surface solve ran already (shape contact, unfold_surface).
UnfoldResult unfold_prepared(const PreparedMesh& prepared, const Options& options,
                             const UnfoldResult* solved) {
  validate_options(options);
  UnfoldResult result;
  result.surface = prepared.surface;
  result.tets = prepared.tets;
  result.tet_report = prepared.tet_report;
  result.warnings = prepared.warnings;
  result.seconds_prepare = prepared.seconds;
  result.seconds_contact = prepared.seconds_contact;

  const auto start = std::chrono::steady_clock::now();
  // A prepared mesh serves every config of a batch or a comparison: the
  // unfolded shape's tets are made here whatever it holds, the input's only
  // if it was deferred.
  // Given tets (prepare_mesh_from_tets) are the user's: never replaced.
  const bool given = prepared.tet_report.route == "given";
  // Given tets that say where they were made (a default run's rest tets) take
  // the unfolded shape's route as they did.
  const bool given_unfolded =
      given && prepared.unfolded_tet_positions.rows() > 0 && tets_from_unfolded(options);
  bool on_unfolded = given_unfolded || (!given && tets_from_unfolded(options) &&
                                        (prepared.tets_deferred || prepared.tets.T.rows() > 0));
  const bool contact_check = !given && tets_from_unfolded_on_contact(options);
  if (contact_check && prepared.tet_report.contact_face_pairs > 0) on_unfolded = true;
  if (!on_unfolded && prepared.tets_deferred) {
    result.tets = tetrahedralize_or_fall_back(result.surface, false, options, &result.tet_report,
                                              &result.warnings);
    sort_interior_vertices(&result.tets);
  }
  bool contact_bridge = false;
  if (contact_check && !on_unfolded && result.tets.T.rows() > 0) {
    const auto start = std::chrono::steady_clock::now();
    contact_bridge =
        some_tet_bridges_contact(result.surface, result.tets, options.contact_geodesic);
    on_unfolded = contact_bridge;
    result.seconds_contact += seconds_since(start);
    LOG(INFO) << (contact_bridge ? "some" : "none") << " of the input's tets bridge a contact ("
              << seconds_since(start) << " s): tetrahedralizing "
              << (on_unfolded ? "the unfolded shape" : "the input");
  }
  // The rotation integration belongs to the cascade methods: LSMDS has no
  // rotations to integrate, SCF's ARAP refinement is its own.
  const bool integrates =
      options.integrate.iterations > 0 && options.method != "scf" && options.method != "lsmds";
  std::future<double> lambda2;
  if (on_unfolded) {
    lambda2 = solve_on_unfolded_tets(options, solved, integrates, &result,
                                     given_unfolded ? &prepared.unfolded_tet_positions : nullptr);
    result.tet_report.contact_face_pairs = prepared.tet_report.contact_face_pairs;
    result.tet_report.contact_bridge = contact_bridge;
  }
  std::vector<double> integrate_factors;
  const EdgeGraph graph = solve_graph(result, integrates ? options.integrate.surface_edges : 0.0,
                                      &integrate_factors, &result.warnings);
  check_tet_graph(graph, result.tets.V);
  result.num_edges = graph.num_edges();
  std::future<GeodesicRows> geodesic_rows = start_geodesic_rows(graph, result.tets.V, options);
  if (options.method == "lsmds") {
    result.cascade = lsmds_cascade_result(graph, result.tets.V, options.lsmds);
  } else if (options.method == "scf") {
    unfold_scf(graph, options.scf, &result);
  } else if (on_unfolded) {
    // the surface solve ran above, before its tets could be made
  } else if (options.domain == "surface" && result.tets.T.rows() > 0) {
    solve_on_surface(graph, options, solved, &result);
  } else {
    solve_cascade(graph, result.tets, options, &result);
  }
  if (integrates)
    integrate_cascade_rotations(graph, integrate_factors, options,
                                lambda2.valid() ? lambda2.get() : surface_lambda2(result.surface),
                                &result);
  result.seconds_unfold = seconds_since(start);
  if (!result.cascade.reached_band)
    result.warnings.push_back("the edge ratio " + std::to_string(result.cascade.edge_ratio) +
                              " did not reach the band within " +
                              std::to_string(options.cascade.num_cascades) + " cascades");
  if (!result.cascade.bounded)
    result.warnings.push_back("beta was below the boundedness bound in some cascade");

  // Back where the input was: the solve fixes only shape, not translation.
  result.tet_canonical = result.cascade.positions;
  result.tet_canonical.rowwise() += result.tets.V.colwise().mean();
  result.canonical.faces = result.surface.faces;
  result.canonical.V = result.tet_canonical.topRows(result.tets.num_surface_vertices);
  if (result.skeleton_canonical.rows() > 0)
    result.skeleton_canonical.rowwise() += result.tets.V.colwise().mean();

  const auto metrics_start = std::chrono::steady_clock::now();
  const Eigen::MatrixX3d& P = result.tets.V;
  const Eigen::MatrixX3d& Q = result.tet_canonical;
  UnfoldMetrics& m = result.metrics;
  constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
  m.E_rig = m.E_str = m.E_geo = kNotComputed;
  m.rigidity_per_vertex = Eigen::VectorXd::Constant(P.rows(), kNotComputed);
  if (computes_metric(options, "E_rig")) {
    const RigidityError rig = rigidity_error(graph, P, Q);
    m.E_rig = rig.mean;
    m.rigidity_per_vertex = rig.per_vertex;
  }
  if (computes_metric(options, "E_str")) {
    const StretchError str = stretch_error(P, Q, options.stretch_metric);
    m.E_str = str.value;
    m.E_str_exact = str.exact;
  }
  m.E_geo_skipped = geodesic_skipped(options, int(P.rows()));
  if (!m.E_geo_skipped.empty()) LOG(INFO) << m.E_geo_skipped;
  if (computes_metric(options, "E_geo") && m.E_geo_skipped.empty()) {
    const GeodesicError geo = geodesic_rows.valid()
                                  ? geodesic_error_solve(geodesic_rows.get(), Q)
                                  : geodesic_error(graph, P, Q, options.geodesic_metric);
    m.E_geo = geo.value;
    m.E_geo_exact = geo.exact;
  }
  // Against the orientation the tets were made with.
  m.inverted_tets = count_inverted_tets(
      result.unfolded_tet_positions.rows() > 0 ? result.unfolded_tet_positions : P, Q,
      result.tets.T);
  m.damage = surface_damage(result.surface.V, result.canonical.V, result.surface.faces);
  m.seconds = seconds_since(metrics_start);
  return result;
}

}  // namespace

UnfoldResult unfold_surface(const SurfaceMesh& input, const Options& options) {
  if (options.components == "separately" && check_surface_mesh(input, false).num_components > 1)
    return unfold_components_separately(input, options);
  PendingTets pending;
  PreparedMesh prepared = prepare_surface(input, options, &pending);
  if (prepared.tets_deferred) return unfold_prepared(prepared, options, nullptr);
  if (!tets_from_unfolded_on_contact(options) || pending.open || !kForkAlongsideThreads) {
    make_input_tets(options, pending, &prepared);
    return unfold_prepared(prepared, options, nullptr);
  }
  // Shape contact: the surface solve needs no tets, and runs while the input's
  // are made (TetGen works in a process of its own).
  const auto start = std::chrono::steady_clock::now();
  const double seconds_surface = prepared.seconds;
  UnfoldResult solved;
  solved.surface = prepared.surface;
  {
    std::future<void> tets =
        std::async(std::launch::async, [&] { make_input_tets(options, pending, &prepared); });
    solve_surface_cascade(options, &solved);
    tets.get();
  }
  prepared.seconds = seconds_surface + seconds_since(start);  // the surface solve's included
  return unfold_prepared(prepared, options, &solved);
}

}  // namespace unfold
