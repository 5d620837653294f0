#include "pipeline/unfold_steps.h"

#include <glog/logging.h>
#include <omp.h>

#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/fork_safety.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "energies/soft_joint_factors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/simplify_surface_mesh.h"
#include "mesh/tet_volumes.h"
#include "mesh/untangle_tets.h"
#include "metrics/edge_ratio.h"
#include "metrics/pose_invariance.h"
#include "metrics/rigidity_error.h"
#include "metrics/stretch_error.h"
#include "solvers/contact_bridges.h"
#include "solvers/filter_change.h"
#include "solvers/prolong_surface_solve.h"
#include "solvers/tetrahedralize_unfolded.h"
#include "stages/anchor_lambda2.h"
#include "stages/find_contact_faces.h"
#include "stages/lsmds_cascade.h"
#include "stages/place_interior.h"
#include "stages/scf_cascade.h"
#include "stages/solve_cascade.h"
#include "stages/tetrahedralize_input.h"
#include "stages/tets_of_unfolded_shape.h"

namespace unfold {
namespace {

// simplify.surface_solve_hops: fewer clusters than this leave no shape to solve.
constexpr int kFewestClusters = 8;
// simplify.surface_solve_vertices: clusters at most this many edges across.
constexpr int kMostAutomaticHops = 8;

// A large surface to solve on clusters (simplify.surface_solve_vertices); not
// with user pairs, which name the whole surface's vertices.
bool exceeds_surface_solve_vertices(const UnfoldState& s) {
  return s.options.surface_solve_hops == 0 && s.options.surface_solve_vertices > 0 &&
         s.mesh.surface.V.rows() > s.options.surface_solve_vertices &&
         s.options.energy.user_pairs_file.empty();
}

Stage step(std::string name, std::function<void(UnfoldState&)> run,
           StagePart part = StagePart::unfold, StageTimer timer = StageTimer::none) {
  return Stage{std::move(name), std::move(run), part, timer, {}, false, false};
}

void append(std::vector<std::string>* to, const std::vector<std::string>& from) {
  to->insert(to->end(), from.begin(), from.end());
}

// Why E_geo is left out though asked for (more tet vertices than
// metrics.geodesic_max_vertices), and how to get it; "" when it is computed.
std::string geodesic_skipped(const Options& options, int num_vertices) {
  const int limit = options.geodesic_max_vertices;
  if (!computes_metric(options, "E_geo") || limit == 0 || num_vertices <= limit) return "";
  return "E_geo left out above " + std::to_string(limit) + " tet vertices (here " +
         std::to_string(num_vertices) +
         "); --metrics E_rig,E_str,E_geo (or metrics.geodesic_max_vertices: 0) computes it";
}

// E_geo's rows of G (and E_geo_surface's) depend on the rest shape alone. Where
// the solve runs on one thread (fewer than kMinParallelRows vertices; LSMDS
// excepted, which runs Dijkstras of its own in parallel), they are computed on
// the other core meanwhile, on one thread so that nothing waits on a shared
// core; the rows must fit in 32 MB. Otherwise E_geo after the solve, in
// parallel. Whether that is so for n vertices:
bool geodesic_rows_beside(const Options& options, int n) {
  const GeodesicErrorOptions& geo = options.geodesic_metric;
  const double rows = n <= geo.exact_limit ? n : std::min(geo.sources, n);
  return computes_metric(options, "E_geo") && geodesic_skipped(options, n).empty() &&
         options.method != "lsmds" && n >= 2 && n < kMinParallelRows &&
         rows * n * sizeof(double) <= (32 << 20);
}

std::future<GeodesicRows> start_geodesic_rows(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                              const Options& options) {
  if (!geodesic_rows_beside(options, graph.num_vertices)) return {};
  return std::async(std::launch::async, [&graph, &P, geo = options.geodesic_metric] {
    omp_set_num_threads(1);
    return geodesic_error_precomputation(graph, P, geo);
  });
}

// The cascade's domain: the surface alone (made by lambda2_and_beta), or the
// tets and their edges.
const EdgeGraph& domain_graph(const UnfoldState& s, CascadeDomain domain) {
  return domain == CascadeDomain::surface ? s.cascade_edges.graph : s.edges.graph;
}

const TetMesh& domain_mesh(const UnfoldState& s, CascadeDomain domain) {
  return domain == CascadeDomain::surface ? s.cascade_mesh : s.mesh.tets;
}

CascadeSetupOptions setup_options(const Options& o) {
  return {{o.method, o.linear_solver, o.ceres},
          o.energy,
          o.beta_mode,
          o.beta_value,
          o.raise_beta_to_bound};
}

void take_setup(UnfoldState& s, CascadeSetup setup) {
  UnfoldResult& r = s.result;
  r.lambda2 = setup.lambda2;
  r.beta_requested = setup.beta.requested;
  r.beta_start = setup.beta.start;
  r.beta_raised = setup.beta.raised;
  r.linear_solver = setup.backend_options.linear_solver.method;
  r.amg_levels = setup.amg_levels;
  r.seconds_amg += setup.seconds_amg;
  append(&r.warnings, setup.warnings);
  s.setup = std::move(setup);
}

// The input's tets made, in place of the surface alone; their warnings go to `warnings`.
void take_input_tets(UnfoldState& s, InputTets t, std::vector<std::string>* warnings) {
  s.mesh.tets = std::move(t.tets);
  s.mesh.tet_report = t.report;
  s.mesh.tets_deferred = false;
  append(warnings, t.warnings);
}

void take_solve(UnfoldResult& r, CascadeSolve solve) {
  r.cascade = std::move(solve.cascade);
  r.linear_solver = solve.linear_solver;
  r.cg = solve.cg;
  append(&r.warnings, solve.warnings);
}

// Where the tets were made: the unfolded shape's positions when the method made
// them there, else the rest. Their orientation there is the upright one.
const Eigen::MatrixX3d& tets_made_at(const UnfoldState& s) {
  return s.result.unfolded_tet_positions.rows() > 0 ? s.result.unfolded_tet_positions
                                                    : s.mesh.tets.V;
}

}  // namespace

Stage check_and_simplify() {
  return step(
      "check and simplify",
      [](UnfoldState& s) {
        const Options& options = s.options;
        const SurfaceMesh& input = *s.input;
        PreparedMesh& prepared = s.mesh;
        validate_options(options);
        const SurfaceReport report = check_surface_mesh(input, true);
        // A tet mesh needs a closed surface. The robust route's winding number
        // closes small holes (cat0 has 76 boundary edges in 83,606); larger ones
        // leave no well-defined inside, and the conforming route needs none at
        // all. The surface graph may stand in when allowed.
        size_t num_sides = 0;
        for (const auto& f : input.faces) num_sides += f.size();
        const bool small_holes = options.tet.route != "conforming" &&
                                 size_t(report.num_boundary_edges) * 200 <= num_sides;
        s.open = report.num_boundary_edges > 0 && !small_holes;
        if (s.open && !options.fallback_surface_graph)
          throw InputError(
              "the surface is open (" + std::to_string(report.num_boundary_edges) +
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
        // until a stage makes tets: unfold_prepared makes the unfolded shape's
        prepared.tets = surface_alone(prepared.surface);
        prepared.tets_deferred = true;
      },
      StagePart::prepare);
}

Stage find_contact() {
  // A route of conforming asks for TetGen's own tets of the input, whose
  // refusal of such a surface is then the answer.
  return step(
             "contact: intersecting faces",
             [](UnfoldState& s) {
               const ContactFaces contact =
                   find_contact_faces(s.mesh.surface, s.options.contact_geodesic);
               s.known_intersections = contact.intersecting_pairs;
               s.mesh.tet_report.contact_face_pairs = contact.contact_pairs;
             },
             StagePart::prepare, StageTimer::contact)
      .when([](const UnfoldState& s) { return !s.open && s.options.tet.route != "conforming"; });
}

Stage tetrahedralize_the_input() {
  return step(
      "tetrahedralize the input",
      [](UnfoldState& s) {
        take_input_tets(
            s,
            tetrahedralize_input(s.mesh.surface, s.open, s.options.tet,
                                 s.options.fallback_surface_graph, s.known_intersections),
            &s.mesh.warnings);
      },
      StagePart::prepare);
}

Stage tetrahedralize_deferred() {
  return step("tetrahedralize the input (deferred)", [](UnfoldState& s) {
    take_input_tets(s,
                    tetrahedralize_input(s.mesh.surface, false, s.options.tet,
                                         s.options.fallback_surface_graph),
                    &s.result.warnings);
  });
}

Stage check_contact_bridges() {
  return step(
             "contact: tets bridging",
             [](UnfoldState& s) {
               s.contact_bridge = some_tet_bridges_contact(s.mesh.surface, s.mesh.tets,
                                                           s.options.contact_geodesic);
               LOG(INFO) << (s.contact_bridge ? "some" : "none")
                         << " of the input's tets bridge a contact: tetrahedralizing "
                         << (s.contact_bridge ? "the unfolded shape" : "the input");
             },
             StagePart::unfold, StageTimer::contact)
      .joining()
      .when(has_tets)
      .unless(given_tets)
      .unless(contact_faces_found);
}

Stage solve_edges() {
  return step("edges", [](UnfoldState& s) {
    s.edges = solve_edge_graph(s.mesh.tets, s.mesh.surface,
                               integrates(s.options) ? s.options.integrate.surface_edges : 0.0);
    append(&s.result.warnings, s.edges.warnings);
    s.result.num_edges = s.edges.graph.num_edges();
    s.geodesic_rows = start_geodesic_rows(s.edges.graph, s.mesh.tets.V, s.options);
  });
}

Stage lambda2_and_beta(CascadeDomain domain) {
  const bool surface = domain == CascadeDomain::surface;
  return step(
      surface ? "surface: lambda_2 and beta" : "lambda_2 and beta",
      [domain, surface](UnfoldState& s) {
        if (surface && s.options.surface_solve_hops > 0) {
          s.coarsening = coarsen_surface(s.mesh.surface, s.options.surface_solve_hops);
        } else if (surface && exceeds_surface_solve_vertices(s)) {
          // Clusters by connectivity alone, so every pose of a mesh gets the same ones.
          for (int hops = 1; hops <= kMostAutomaticHops; ++hops) {
            s.coarsening = coarsen_surface(s.mesh.surface, hops);
            if (s.coarsening.V.rows() <= s.options.surface_solve_vertices) break;
          }
          LOG(INFO) << "simplify.surface_solve_vertices: " << s.mesh.surface.V.rows()
                    << " surface vertices, above " << s.options.surface_solve_vertices;
        }
        if (s.coarsening.V.rows() > 0 && s.coarsening.V.rows() < kFewestClusters) {
          s.result.warnings.push_back(
              "the surface's clusters (simplify.surface_solve_hops, "
              "surface_solve_vertices) are " +
              std::to_string(s.coarsening.V.rows()) + "; the surface is solved whole");
          LOG(WARNING) << s.result.warnings.back();
          s.coarsening = SurfaceCoarsening{};
        }
        if (surface && coarse_surface_solve(s)) {  // on a coarse graph of the surface
          s.cascade_mesh = TetMesh{s.coarsening.V, Eigen::MatrixX4i(), int(s.coarsening.V.rows())};
          s.cascade_edges = SolveEdges{s.coarsening.graph, {}, {}};
          LOG(INFO) << "surface solve on " << s.coarsening.V.rows() << " clusters of the "
                    << s.mesh.surface.V.rows() << " surface vertices";
        } else if (surface) {  // the energy on the surface's vertices and triangle edges
          s.cascade_mesh = surface_alone(s.mesh.surface);
          s.cascade_edges = solve_edge_graph(s.cascade_mesh, s.mesh.surface, 0.0);
        }
        take_setup(s, setup_cascade(domain_graph(s, domain), domain_mesh(s, domain), s.mesh.surface,
                                    setup_options(s.options), {}, s.coarsening.masses));
        s.first_solver = s.setup.backend_options.linear_solver.method;
        s.first_setup = {s.setup.problem->distance_clusters, s.setup.fiedler_vector};
      },
      StagePart::unfold, StageTimer::lambda2);
}

Stage cascade(CascadeDomain domain) {
  return step(
      domain == CascadeDomain::surface ? "surface: cascade" : "cascade",
      [](UnfoldState& s) {
        take_solve(s.result, solve_cascade(std::move(s.setup), s.options.cascade));
      },
      StagePart::unfold, StageTimer::cascade);
}

// The first solve converged as far as the second: stopped earlier (100 times
// cascade.epsilon), its joints differ enough to move wolf's mean pose ratio
// from 0.19 to 0.28 (docs/method.md, soft joints).
Stage soft_joints_lambda2(CascadeDomain domain) {
  return step(
      "soft joints: lambda_2 and beta",
      [domain](UnfoldState& s) {
        // The reweighted matrices have the first solve's pattern, so its solver
        // serves them: no second symbolic analysis, and no speculative AMG
        // hierarchy built only to be dropped.
        CascadeSetupOptions softened = setup_options(s.options);
        softened.backend.linear_solver.method = s.first_solver;
        s.first_solution = s.result.cascade.positions;
        s.first_iterations = s.result.cascade.iterations;
        const EdgeGraph& graph = domain_graph(s, domain);
        const TetMesh& mesh = domain_mesh(s, domain);
        take_setup(
            s, setup_cascade(graph, mesh, s.mesh.surface, softened,
                             soft_joint_factors(graph, mesh.V, s.first_solution, s.options.soften),
                             s.coarsening.masses, &s.first_setup));
      },
      StagePart::unfold, StageTimer::lambda2);
}

Stage soft_joints_cascade(CascadeDomain) {
  return step(
      "soft joints: cascade",
      [](UnfoldState& s) {
        CascadeOptions cascade = s.options.cascade;
        if (s.options.soften.epsilon > 0) cascade.epsilon = s.options.soften.epsilon;
        take_solve(s.result, solve_cascade(std::move(s.setup), cascade, &s.first_solution));
        LOG(INFO) << "soft joints: " << s.first_iterations << " iterations, then "
                  << s.result.cascade.iterations << " with the joints softened";
      },
      StagePart::unfold, StageTimer::cascade);
}

Stage soft_joints_filter(CascadeDomain domain) {
  return step(
             "soft joints: filter",
             [domain](UnfoldState& s) {
               const double unit = std::sqrt(surface_area(s.mesh.surface));
               s.result.cascade.positions = filter_change(
                   domain_graph(s, domain), domain_mesh(s, domain).V, s.first_solution,
                   s.result.cascade.positions,
                   {s.options.soften.filter * unit, s.options.soften.filter_stretch * unit});
             },
             StagePart::unfold, StageTimer::cascade)
      .when(filters_soft_joints);
}

Stage full_resolution() {
  return step(
      "surface: to full resolution",
      [](UnfoldState& s) {
        const EdgeGraph graph =
            build_edge_graph(int(s.mesh.surface.V.rows()), triangulate_faces(s.mesh.surface));
        s.result.cascade.positions = prolong_surface_solve(graph, s.mesh.surface.V, s.coarsening,
                                                           s.result.cascade.positions);
      },
      StagePart::unfold, StageTimer::cascade);
}

Stage tets_of_unfolded() {
  return step(
      "tets of the unfolded shape",
      [](UnfoldState& s) {
        TetOptions tet = s.options.tet;
        if (coarse_surface_solve(s))
          tet.interior_spacing = input_interior_spacing(s.mesh.surface, s.result.cascade.positions);
        UnfoldedShapeTets u =
            tets_of_unfolded_shape(s.mesh.surface, s.result.cascade.positions, tet,
                                   integrates(s.options) && s.options.integrate.surface_edges > 0);
        TetReport& report = s.mesh.tet_report;
        const int contact_face_pairs = report.contact_face_pairs;
        s.mesh.tets = std::move(u.rest);
        report = u.report;
        report.contact_face_pairs = contact_face_pairs;
        report.contact_bridge = s.contact_bridge;
        s.result.cascade.positions = std::move(u.positions);
        s.result.unfolded_tet_positions = std::move(u.unfolded);
      },
      StagePart::unfold, StageTimer::unfolded_tets);
}

Stage given_unfolded_shape() {
  return step("given tets' unfolded shape", [](UnfoldState& s) {
    // Its surface is this solve's, its interior where the tets were made: the
    // start tets_of_unfolded gave the run that wrote them.
    Eigen::MatrixX3d unfolded = s.mesh.unfolded_tet_positions;
    unfolded.topRows(s.mesh.surface.V.rows()) = s.result.cascade.positions;
    s.result.cascade.positions = unfolded.rowwise() - unfolded.colwise().mean();
    s.result.unfolded_tet_positions = std::move(unfolded);
  });
}

Stage interior_placement() {
  return step(
             "interior placement",
             [](UnfoldState& s) {
               Eigen::MatrixX3d& positions = s.result.cascade.positions;
               positions = place_interior(s.edges.graph, s.mesh.tets, positions);
             },
             StagePart::unfold, StageTimer::interior)
      .when(has_tets);
}

Stage lsmds_solve() {
  return step(
      "lsmds",
      [](UnfoldState& s) {
        s.result.cascade = lsmds_cascade(s.edges.graph, s.mesh.tets.V, s.options.lsmds);
      },
      StagePart::unfold, StageTimer::cascade);
}

Stage scf_solve() {
  return step(
      "scf",
      [](UnfoldState& s) {
        UnfoldResult& r = s.result;
        ScfCascade c = scf_cascade(s.edges.graph, s.mesh.tets, s.mesh.surface, s.options.scf);
        r.cascade = std::move(c.cascade);
        r.skeleton = std::move(c.skeleton);
        r.skeleton_canonical = std::move(c.skeleton_canonical);
        append(&r.warnings, c.warnings);
      },
      StagePart::unfold, StageTimer::cascade);
}

Stage surface_geodesic_rows() {
  return step("metrics: the surface's geodesic rows",
              [](UnfoldState& s) {
                omp_set_num_threads(1);
                s.surface_geodesic_rows = surface_geodesic_error_precomputation(
                    s.mesh.surface.V, triangulate_faces(s.mesh.surface), s.options.geodesic_metric);
              })
      .when([](const UnfoldState& s) {
        return geodesic_rows_beside(s.options, int(s.mesh.surface.V.rows()));
      })
      .on_the_side(kForkAlongsideThreads);
}

Stage anchor_unit() {
  return step("integration: anchor lambda_2",
              [](UnfoldState& s) { s.anchor_lambda2 = anchor_lambda2(s.mesh.surface); });
}

// integrate: the cascade's rotation field integrated on the whole tet mesh
// (docs/method.md, pose invariance), anchored in units of anchor_unit.
Stage integration() {
  return step(
             "integration",
             [](UnfoldState& s) {
               s.integrated = integrate_rotations(s.edges.graph, s.mesh.tets.V,
                                                  s.result.cascade.positions, s.anchor_lambda2,
                                                  s.options.integrate, s.edges.integrate_factors);
             },
             StagePart::unfold, StageTimer::integration)
      .joining();
}

Stage anchored() {
  return step(
      "anchored steps",
      [](UnfoldState& s) {
        const Eigen::MatrixX3d& P = s.mesh.tets.V;
        CascadeResult& c = s.result.cascade;
        ArapSolveReport steps;
        c.positions = anchored_steps(s.edges.graph, P, std::move(s.integrated), &steps);
        s.result.anchored_steps = steps.steps;
        s.result.anchored_converged = steps.converged;
        c.edge_ratio = edge_ratio(s.edges.graph, P, c.positions);
        c.reached_band = in_band(c.edge_ratio, s.options.cascade.edge_ratio_band);
      },
      StagePart::unfold, StageTimer::anchored);
}

Stage untangle() {
  return step("untangle", [](UnfoldState& s) {
    const TetMesh& tets = s.mesh.tets;
    if (tets.T.rows() == 0) return;  // the surface's edge graph: no tets to mend
    const Eigen::MatrixXi faces = triangulate_faces(s.mesh.surface);
    s.result.untangle = untangle_tets(tets_made_at(s), tets.V, tets.T, s.options.untangle,
                                      &s.result.cascade.positions, &faces);
    const UntangleReport& r = s.result.untangle;
    report_detail([&](std::ostream& line) {
      line << "untangled: " << r.inverted_before << " inverted tets, " << r.inverted_after
           << " after " << r.sweeps << " passes; " << r.moved_vertices
           << " vertices moved, at most " << r.largest_move << " of their shortest edge";
    });
  });
}

Stage measure() {
  return step(
      "metrics",
      [](UnfoldState& s) {
        const Options& options = s.options;
        UnfoldResult& result = s.result;
        const SurfaceMesh& surface = s.mesh.surface;
        const Eigen::MatrixX3i faces = triangulate_faces(surface);
        const TetMesh& tets = s.mesh.tets;  // moved last: E_geo's rows read it until their get()
        result.warnings.insert(result.warnings.begin(), s.mesh.warnings.begin(),
                               s.mesh.warnings.end());
        if (!result.cascade.reached_band)
          result.warnings.push_back("the edge ratio " + std::to_string(result.cascade.edge_ratio) +
                                    " did not reach the band within " +
                                    std::to_string(options.cascade.num_cascades) + " cascades");
        if (!result.cascade.bounded)
          result.warnings.push_back("beta was below the boundedness bound in some cascade");
        // Back where the input was: the solve fixes only shape, not translation.
        result.tet_canonical = result.cascade.positions;
        result.tet_canonical.rowwise() += tets.V.colwise().mean();
        result.canonical.faces = surface.faces;
        result.canonical.V = result.tet_canonical.topRows(tets.num_surface_vertices);
        if (result.skeleton_canonical.rows() > 0)
          result.skeleton_canonical.rowwise() += tets.V.colwise().mean();

        const EdgeGraph& graph = s.edges.graph;
        const Eigen::MatrixX3d& P = tets.V;
        const Eigen::MatrixX3d& Q = result.tet_canonical;
        UnfoldMetrics& m = result.metrics;
        constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
        m.E_rig = m.E_str = m.E_geo = m.E_geo_surface = kNotComputed;
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
          const GeodesicError geo = s.geodesic_rows.valid()
                                        ? geodesic_error_solve(s.geodesic_rows.get(), Q)
                                        : geodesic_error(graph, P, Q, options.geodesic_metric);
          m.E_geo = geo.value;
          m.E_geo_exact = geo.exact;
          const std::optional<GeodesicRows>& rows = s.surface_geodesic_rows;
          m.E_geo_surface = (rows ? surface_geodesic_error_solve(*rows, result.canonical.V)
                                  : surface_geodesic_error(surface.V, faces, result.canonical.V,
                                                           options.geodesic_metric))
                                .value;
        }
        // Against the orientation the tets were made with.
        m.inverted_tets = count_inverted_tets(tets_made_at(s), Q, tets.T);
        m.damage = surface_damage(surface.V, result.canonical.V, surface.faces);
        m.folds = surface_folds(surface.V, result.canonical.V, faces);
        result.surface = std::move(s.mesh.surface);
        result.tets = std::move(s.mesh.tets);
        result.tet_report = s.mesh.tet_report;
      },
      StagePart::metrics);
}

bool surface_open(const UnfoldState& state) { return state.open; }

bool untangles(const Options& options) { return options.untangle.sweeps > 0; }

StageList finish(const Options& options) {
  StageList stages;
  if (untangles(options)) stages.push_back(untangle());
  // Joining: the surface's geodesic rows may still run beside.
  stages.push_back(measure().joining());
  return stages;
}

bool coarse_surface_solve(const UnfoldState& state) { return state.coarsening.V.rows() > 0; }

bool contact_faces_found(const UnfoldState& state) {
  return state.mesh.tet_report.contact_face_pairs > 0;
}

bool has_tets(const UnfoldState& state) { return state.mesh.tets.T.rows() > 0; }

bool given_tets(const UnfoldState& state) { return state.mesh.tet_report.route == "given"; }

bool tets_deferred(const UnfoldState& state) { return state.mesh.tets_deferred; }

bool keeps_input_tets(const UnfoldState& state) {
  return given_tets(state) || !(state.mesh.tets_deferred || has_tets(state));
}

bool given_tets_made_unfolded(const UnfoldState& state) {
  return given_tets(state) && state.mesh.unfolded_tet_positions.rows() > 0;
}

bool contact(const UnfoldState& state) {
  return !given_tets(state) && (contact_faces_found(state) || state.contact_bridge);
}

bool softens(const Options& options) {
  return options.soften.scale > 0 && options.energy.arap_weight > 0;
}

bool filters_soft_joints(const UnfoldState& state) {
  return state.options.soften.filter > 0 || state.options.soften.filter_stretch > 0;
}

bool integrates(const Options& options) {
  return options.integrate.iterations > 0 && options.method != "scf" && options.method != "lsmds";
}

}  // namespace unfold
