// Graceful paths and numerical guards through the library: the surface-graph
// fallback, components unfolded separately, beta raised above the bound, NaN
// stopping the cascade at a named iteration, and a cascade that misses the
// edge-ratio band reporting it.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "metrics/surface_damage.h"
#include "pipeline/metrics_json.h"
#include "pipeline/unfold_surface.h"
#include "solvers/cascade.h"
#include "solvers/local_global.h"
#include "test_files.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

using test::Contains;

const Options kDefaults;

bool has_warning(const UnfoldResult& r, const std::string& words) {
  for (const auto& w : r.warnings)
    if (w.find(words) != std::string::npos) return true;
  return false;
}

// Small, fast options: a handful of iterations is enough to exercise each path.
Options quick_options() {
  Options options;
  options.cascade.k_iter = 3;
  options.cascade.num_cascades = 2;
  return options;
}

// The sphere with the faces around its north pole removed: a hole.
SurfaceMesh sphere_with_hole() {
  SurfaceMesh mesh = test::uv_sphere(8, 12);
  std::vector<std::vector<int>> kept;
  for (const auto& f : mesh.faces)
    if (f[0] != 0) kept.push_back(f);
  mesh.faces = kept;
  mesh.V = mesh.V.bottomRows(mesh.V.rows() - 1).eval();  // vertex 0 is now unused
  for (auto& f : mesh.faces)
    for (int& v : f) --v;
  return mesh;
}

// The metrics JSON write_metrics_json produces for r.
std::string metrics_json_text(const UnfoldResult& r, const Options& options) {
  const test::TempDir dir;
  write_metrics_json(dir.file("m.json"), r, options);
  std::stringstream json;
  json << std::ifstream(dir.file("m.json")).rdbuf();
  return json.str();
}

SurfaceMesh disjoint_union(const SurfaceMesh& a, const SurfaceMesh& b, double shift) {
  SurfaceMesh both = a;
  both.V.conservativeResize(a.V.rows() + b.V.rows(), 3);
  both.V.bottomRows(b.V.rows()) = b.V.array() + shift;
  for (auto f : b.faces) {
    for (int& v : f) v += int(a.V.rows());
    both.faces.push_back(f);
  }
  return both;
}

TEST(SurfaceGraphFallback, OpenSurfaceIsRefusedUnlessAllowed) {
  const SurfaceMesh open = sphere_with_hole();
  EXPECT_TRUE(Contains(test::error_message<InputError>([&] { unfold_surface(open, kDefaults); }),
                       "fallback_surface_graph"));
  Options options = quick_options();
  options.fallback_surface_graph = true;
  const UnfoldResult r = unfold_surface(open, options);
  EXPECT_EQ(r.tet_report.route, "surface_graph");
  EXPECT_EQ(r.tets.T.rows(), 0);
  EXPECT_EQ(r.canonical.V.rows(), open.V.rows());
  EXPECT_EQ(r.canonical.faces, open.faces);
  EXPECT_TRUE(r.canonical.V.allFinite());
  // The graph is the triangles' edges: V + F - E = 1 for a disc (Euler).
  EXPECT_EQ(r.num_edges, int(open.V.rows() + open.faces.size()) - 1);
  EXPECT_TRUE(has_warning(r, "no tet mesh (the surface is open): unfolding on the surface edge"));
}

TEST(SurfaceGraphFallback, TetGenFailureFallsBackWhenAllowed) {
  const SurfaceMesh folded =
      read_surface_mesh(UNFOLD_SOURCE_DIR "/tests/bad_inputs/self_intersecting.off");
  // The conforming route fails on it (the default auto route would fall back
  // to the robust route instead, which carves any surface; the default shape
  // would tetrahedralize the unfolded shape).
  Options conforming = kDefaults;
  conforming.tet_shape = "input";
  conforming.tet.route = "conforming";
  EXPECT_TRUE(
      Contains(test::error_message<NumericalError>([&] { unfold_surface(folded, conforming); }),
               "tetrahedralize.fallback_surface_graph: true"));
  Options options = quick_options();
  options.tet_shape = "input";
  options.tet.route = "conforming";
  options.fallback_surface_graph = true;
  const UnfoldResult r = unfold_surface(folded, options);
  EXPECT_EQ(r.tet_report.route, "surface_graph");
  EXPECT_TRUE(r.canonical.V.allFinite());
  EXPECT_TRUE(has_warning(r, "no tet mesh (tetrahedralization (conforming route): TetGen"));
}

TEST(Components, RefusedWithTheirCountByDefault) {
  const SurfaceMesh two = disjoint_union(test::uv_sphere(6, 8), test::octahedron(), 5.0);
  EXPECT_TRUE(Contains(test::error_message<InputError>([&] { unfold_surface(two, kDefaults); }),
                       "2 connected components"));
}

TEST(Components, UnfoldedSeparatelyAndPutBackInInputOrder) {
  const SurfaceMesh a = test::uv_sphere(6, 8), b = test::uv_sphere(5, 7, 0.5);
  const SurfaceMesh two = disjoint_union(a, b, 4.0);
  Options options = quick_options();
  options.components = "separately";
  const UnfoldResult r = unfold_surface(two, options);
  ASSERT_EQ(r.canonical.V.rows(), two.V.rows());
  EXPECT_EQ(r.canonical.faces, two.faces);
  EXPECT_EQ(r.surface.V, two.V);
  EXPECT_TRUE(has_warning(r, "2 connected components unfolded separately"));

  // Each block of rows is exactly that component unfolded alone.
  const UnfoldResult ra = unfold_surface(a, options);
  SurfaceMesh b_shifted = b;
  b_shifted.V.array() += 4.0;
  const UnfoldResult rb = unfold_surface(b_shifted, options);
  EXPECT_EQ(r.canonical.V.topRows(a.V.rows()), ra.canonical.V);
  EXPECT_EQ(r.canonical.V.bottomRows(b.V.rows()), rb.canonical.V);
  // The merged tet mesh keeps every surface vertex first, then the interiors.
  EXPECT_EQ(r.tets.num_surface_vertices, two.V.rows());
  EXPECT_EQ(r.tets.V.rows(), ra.tets.V.rows() + rb.tets.V.rows());
  EXPECT_EQ(r.tets.T.rows(), ra.tets.T.rows() + rb.tets.T.rows());
  EXPECT_EQ(r.tets.V.topRows(two.V.rows()), two.V);
  EXPECT_EQ(r.tet_canonical.topRows(two.V.rows()), r.canonical.V);
  EXPECT_EQ(r.cascade.iterations, ra.cascade.iterations + rb.cascade.iterations);
  EXPECT_EQ(r.num_edges, ra.num_edges + rb.num_edges);
  EXPECT_EQ(connected_components(build_edge_graph(int(r.tets.V.rows()), r.tets.T)), 2);
}

TEST(Components, MergedPerVertexFieldsAndERigAreOverAllTetVertices) {
  // Parts of different vertex-to-edge ratios, so a mean weighted by edges
  // differs from one weighted by vertices.
  const SurfaceMesh a = test::uv_sphere(8, 12), b = test::octahedron();
  Options options = quick_options();
  options.components = "separately";
  const UnfoldResult r = unfold_surface(disjoint_union(a, b, 5.0), options);
  SurfaceMesh b_shifted = b;
  b_shifted.V.array() += 5.0;
  const UnfoldResult ra = unfold_surface(a, options), rb = unfold_surface(b_shifted, options);
  const Eigen::VectorXd& rig = r.metrics.rigidity_per_vertex;
  ASSERT_EQ(rig.size(), r.tets.V.rows());
  // Surface vertices in input order, then each part's interior vertices.
  const Eigen::Index na = a.V.rows(), nb = b.V.rows();
  EXPECT_EQ(rig.head(na), ra.metrics.rigidity_per_vertex.head(na));
  EXPECT_EQ(rig.segment(na, nb), rb.metrics.rigidity_per_vertex.head(nb));
  const Eigen::Index interior_a = ra.tets.V.rows() - na;
  EXPECT_EQ(rig.segment(na + nb, interior_a), ra.metrics.rigidity_per_vertex.tail(interior_a));
  const double va = double(ra.tets.V.rows()), vb = double(rb.tets.V.rows());
  EXPECT_NEAR(r.metrics.E_rig, rig.mean(), 1e-12);
  EXPECT_NEAR(r.metrics.E_rig, (ra.metrics.E_rig * va + rb.metrics.E_rig * vb) / (va + vb), 1e-12);
  const double by_edges = (ra.metrics.E_rig * ra.num_edges + rb.metrics.E_rig * rb.num_edges) /
                          (ra.num_edges + rb.num_edges);
  EXPECT_GT(std::abs(r.metrics.E_rig - by_edges), 1e-6);  // the old weighting would differ
  EXPECT_EQ(r.metrics.inverted_tets, ra.metrics.inverted_tets + rb.metrics.inverted_tets);
  EXPECT_EQ(r.untangle.inverted_before, ra.untangle.inverted_before + rb.untangle.inverted_before);
  EXPECT_EQ(r.untangle.moved_vertices, ra.untangle.moved_vertices + rb.untangle.moved_vertices);
  // The damage measure: over the merged surface, as over any output (issue 44).
  const SurfaceDamage d = surface_damage(r.surface.V, r.canonical.V, r.surface.faces);
  EXPECT_EQ(r.metrics.damage.edges, ra.metrics.damage.edges + rb.metrics.damage.edges);
  EXPECT_EQ(r.metrics.damage.edges, d.edges);
  EXPECT_EQ(r.metrics.damage.ratio_p999, d.ratio_p999);
  EXPECT_EQ(r.metrics.damage.per_vertex, d.per_vertex);
  EXPECT_EQ(r.metrics.damage.per_vertex.size(), r.canonical.V.rows());
}

TEST(Components, SimplifiedComponentsFollowOneAnother) {
  const SurfaceMesh two = disjoint_union(test::uv_sphere(12, 24), test::uv_sphere(10, 20), 4.0);
  Options options = quick_options();
  options.components = "separately";
  options.target_vertices = 100;
  const UnfoldResult r = unfold_surface(two, options);
  EXPECT_LT(r.surface.V.rows(), two.V.rows());
  EXPECT_EQ(r.canonical.V.rows(), r.surface.V.rows());
  EXPECT_EQ(check_surface_mesh(r.surface, false).num_components, 2);
  EXPECT_EQ(check_surface_mesh(r.canonical, false).num_components, 2);
  EXPECT_EQ(r.tets.V.topRows(r.surface.V.rows()), r.surface.V);
}

// The bound is k (n / lambda_2 - 1) with k the squared spread's weight: the
// paper's k = 1 and the default's small k alike.
TEST(BetaGuard, BetaBelowTheBoundIsRaisedAndReported) {
  const SurfaceMesh sphere = test::uv_sphere(8, 12);
  for (const double k : {0.03, 1.0}) {
    Options options = quick_options();
    options.energy.stretch_weight = k;
    options.energy.stretch_distance = 0;  // the bound is the squared spread's
    options.beta_value = 0.5 * k;         // half of k n / lambda_2: below the bound
    const UnfoldResult r = unfold_surface(sphere, options);
    EXPECT_TRUE(r.beta_raised) << k;
    const double scale = r.beta_requested / (0.5 * k);  // n / lambda_2
    EXPECT_NEAR(r.beta_start, k * (1.01 * scale - 1), 1e-9 * scale) << k;
    EXPECT_TRUE(r.cascade.bounded) << k;
    EXPECT_TRUE(has_warning(r, "raised to")) << k;
  }
  Options options = quick_options();
  options.energy.stretch_weight = 1;
  options.energy.stretch_distance = 0;
  options.beta_value = 0.5;
  const UnfoldResult r = unfold_surface(sphere, options);

  const std::string json = metrics_json_text(r, options);
  EXPECT_TRUE(Contains(json, "\"beta_raised\": true"));
  EXPECT_TRUE(Contains(json, "raised to"));

  options.raise_beta_to_bound = false;  // then the cascade runs unbounded, and says so
  const UnfoldResult unraised = unfold_surface(sphere, options);
  EXPECT_FALSE(unraised.beta_raised);
  EXPECT_FALSE(unraised.cascade.bounded);
  EXPECT_TRUE(has_warning(unraised, "beta was below the bound"));
}

TEST(BetaGuard, HugeBetaCountsAsBounded) {
  Options options = quick_options();
  options.beta_mode = "absolute";
  options.beta_value = 1e200;  // -n I vanishes in rounding: no negative pivot at all
  const UnfoldResult r = unfold_surface(test::uv_sphere(8, 12), options);
  EXPECT_TRUE(r.cascade.bounded);
  EXPECT_FALSE(r.beta_raised);
}

TEST(NumericalGuard, NanInAnIterationIsAnErrorNamingIt) {
  TetMesh grid = test::grid_tet_mesh(3, 2, 2);
  grid.V(5, 1) = std::numeric_limits<double>::quiet_NaN();
  const test::ProblemFixture f(grid);
  CascadeOptions options;
  options.beta = 100;
  EXPECT_TRUE(Contains(test::error_message<NumericalError>([&] {
                         LocalGlobalBackend backend(f.problem);
                         run_cascade(f.problem, backend, options);
                       }),
                       "non-finite positions at iteration 1 (cascade 1"));
}

TEST(NumericalGuard, OverflowingBetaFailsTheFactorizationCleanly) {
  Options options = quick_options();
  options.beta_mode = "absolute";
  options.beta_value = 1e308;  // (beta + 1) L overflows to inf
  EXPECT_TRUE(Contains(
      test::error_message<NumericalError>([&] { unfold_surface(test::uv_sphere(8, 12), options); }),
      "factorizing the global matrix failed at beta = 1e+308"));
}

TEST(NumericalGuard, CascadeMissingTheBandIsReported) {
  Options options;
  options.cascade.k_iter = 1;
  options.cascade.num_cascades = 1;
  options.cascade.edge_ratio_band = {2.0, 3.0};  // out of reach
  const UnfoldResult r = unfold_surface(test::uv_sphere(8, 12), options);
  EXPECT_FALSE(r.cascade.reached_band);
  EXPECT_TRUE(has_warning(r, "did not reach the band"));
  EXPECT_TRUE(Contains(metrics_json_text(r, options), "\"reached_band\": false"));
}

}  // namespace
}  // namespace unfold
