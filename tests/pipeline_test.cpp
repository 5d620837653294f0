// End to end through the library: real TOSCA meshes (skipped without the
// shared data) and pose invariance on the generated shape.
#include <gtest/gtest.h>

#include "core/errors.h"
#include "mesh/coarsen_surface.h"
#include "mesh/read_surface_mesh.h"
#include "metrics/rigid_alignment.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

double rms_radius(const Eigen::MatrixX3d& V) {
  const Eigen::RowVector3d centroid = V.colwise().mean();
  return std::sqrt((V.rowwise() - centroid).rowwise().squaredNorm().mean());
}

class PipelineWolf : public ::testing::TestWithParam<const char*> {};

TEST_P(PipelineWolf, UnfoldsWithThePapersQuality) {
  const std::string path = test::shared_data(std::string("tosca/") + GetParam() + ".off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/" << GetParam() << ".off";
  const SurfaceMesh input = read_surface_mesh(path);
  const UnfoldResult r = unfold_surface(input, paper_options());
  ASSERT_EQ(r.canonical.V.rows(), 4344);
  EXPECT_EQ(r.canonical.faces, input.faces);
  EXPECT_TRUE(r.canonical.V.allFinite());
  EXPECT_TRUE(r.cascade.reached_band);
  EXPECT_GE(r.cascade.edge_ratio, 0.95);
  EXPECT_LE(r.cascade.edge_ratio, 1.05);
  EXPECT_LT(r.metrics.E_rig, 0.7);
  EXPECT_GT(r.metrics.E_str, 0.05);
  // Limbs stretched out: the shape spreads away from its centroid.
  EXPECT_GT(rms_radius(r.canonical.V), 1.05 * rms_radius(input.V));
}

INSTANTIATE_TEST_SUITE_P(Tosca, PipelineWolf, ::testing::Values("wolf0", "wolf1", "wolf2"));

TEST(PipelinePose, CanonicalFormsOfTwoPosesAreCloserThanThePoses) {
  const SurfaceMesh a = make_articulated_shape(ShapePose::preset(0));
  const SurfaceMesh b = make_articulated_shape(ShapePose::preset(1));
  const Options paper = load_options(UNFOLD_SOURCE_DIR "/configs/paper.yaml");
  const UnfoldResult ua = unfold_surface(a, paper);
  const UnfoldResult ub = unfold_surface(b, paper);
  const double before = aligned_distance(a.V, b.V);
  const double after = aligned_distance(ua.canonical.V, ub.canonical.V);
  EXPECT_LT(after, 0.5 * before) << "poses " << before << " apart, canonical forms " << after;
}

// configs/invariant.yaml (a converged surface solve, its rotations integrated):
// every pair of the demo shape's poses ends at most 0.3 times as far apart as
// it started, with the input's local detail back (E_rig of the paper's order:
// at most 1.5 times the paper config's on the same pose, over the same edges
// where the solve joins the surface's to the tets').
// configs/contact.yaml (the same on the unfolded shape's tets) does so with the
// poses whose legs touch or pass through each other too; its tets were made on
// a surface curved otherwise than the input (straight joints), so a few flat
// ones come out inverted at rest and stay so (at most max_inverted of them).
void expect_nearly_one_canonical_form(Options options, const std::string& config,
                                      const std::vector<ShapePose>& shape_poses,
                                      double max_inverted = 0) {
  options.metrics = {"E_rig"};  // the one asserted (E_str and E_geo: a quarter of a run)
  Options paper = paper_options();
  paper.metrics = {"E_rig"};
  const int count = int(shape_poses.size());
  std::vector<SurfaceMesh> poses;
  std::vector<UnfoldResult> forms;
  for (int pose = 0; pose < count; ++pose) {
    poses.push_back(make_articulated_shape(shape_poses[size_t(pose)]));
    forms.push_back(unfold_surface(poses.back(), options));
    ASSERT_EQ(forms.back().canonical.V.rows(), poses.back().V.rows()) << config;
    const double paper_rig = unfold_surface(poses.back(), paper).metrics.E_rig;
    EXPECT_LT(forms.back().metrics.E_rig, 1.5 * paper_rig) << config << ", pose " << pose;
    EXPECT_LE(forms.back().metrics.inverted_tets, max_inverted * double(forms.back().tets.T.rows()))
        << config << ", pose " << pose;
  }
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b) {
      const double before = aligned_distance(poses[size_t(a)].V, poses[size_t(b)].V);
      const double after =
          aligned_distance(forms[size_t(a)].canonical.V, forms[size_t(b)].canonical.V);
      EXPECT_LT(after, 0.3 * before) << config << ", poses " << a << ", " << b << ": " << before
                                     << " apart, canonical forms " << after;
    }
}

Options config(const std::string& name) {
  return load_options(UNFOLD_SOURCE_DIR "/configs/" + name);
}

std::vector<ShapePose> presets() {
  std::vector<ShapePose> poses;
  for (int k = 0; k < ShapePose::num_presets(); ++k) poses.push_back(ShapePose::preset(k));
  return poses;
}

TEST(PipelinePose, InvariantConfigGivesNearlyOneCanonicalForm) {
  expect_nearly_one_canonical_form(config("invariant.yaml"), "invariant.yaml", presets());
}

TEST(PipelinePose, ContactConfigGivesNearlyOneCanonicalFormWhereLegsTouch) {
  std::vector<ShapePose> poses = presets();
  for (int k = 0; k < ShapePose::num_contact_poses(); ++k) poses.push_back(ShapePose::contact(k));
  expect_nearly_one_canonical_form(config("contact.yaml"), "contact.yaml", poses, 0.02);
}

// The default (configs/default.yaml: shape auto) takes the unfolded shape's
// tets for every pose, those whose legs touch included: all of them end nearly
// at one canonical form.
TEST(PipelinePose, DefaultGivesNearlyOneCanonicalFormWhereLegsTouch) {
  std::vector<ShapePose> poses = presets();
  for (int k = 0; k < ShapePose::num_contact_poses(); ++k) poses.push_back(ShapePose::contact(k));
  expect_nearly_one_canonical_form(config("default.yaml"), "default.yaml", poses, 0.02);
}

// simplify.surface_solve_hops: the surface stages on clusters one edge across
// (a quarter of the vertices), carried to all of them, keep the poses'
// canonical forms together.
TEST(PipelinePose, ACoarseSurfaceSolveGivesNearlyOneCanonicalForm) {
  Options options = config("default.yaml");
  options.surface_solve_hops = 1;
  expect_nearly_one_canonical_form(options, "default.yaml, surface_solve_hops", presets(), 0.02);
}

// simplify.surface_solve_vertices: a surface above the limit is solved on the
// clusters of the fewest hops that leave at most that many, exactly as
// surface_solve_hops would; at or below it, on the whole surface.
TEST(PipelineSurfaceDomain, SurfaceSolveVerticesPicksTheFewestHopsUnderTheLimit) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 40);
  Options base = config("default.yaml");
  base.metrics.clear();
  const auto canonical = [&](int hops, int limit) {
    Options options = base;
    options.surface_solve_hops = hops;
    options.surface_solve_vertices = limit;
    return unfold_surface(shape, options).canonical.V;
  };
  const int n = int(shape.V.rows());
  const int one_hop = int(coarsen_surface(shape, 1).V.rows());
  ASSERT_LT(one_hop, n / 2);
  ASSERT_GE(one_hop, 101);  // the smallest limit allowed is 100
  const Eigen::MatrixX3d whole = canonical(0, 0);
  EXPECT_EQ(canonical(0, n), whole);
  const Eigen::MatrixX3d hops1 = canonical(1, 0);
  EXPECT_NE(hops1, whole);
  EXPECT_EQ(canonical(0, one_hop), hops1);
  EXPECT_EQ(canonical(0, one_hop - 1), canonical(2, 0));
  Options bad = base;
  bad.surface_solve_vertices = 99;
  EXPECT_THROW(validate_options(bad), UsageError);
}

// Crossed legs pass through each other: shape contact decides on the contact
// from the intersecting faces, without the input's tets, and ends where
// checking the input's tets (as a mesh prepared with them makes it) ends.
TEST(PipelinePose, ContactFromIntersectingFacesSkipsOnlyTheInputsTets) {
  const SurfaceMesh crossed = make_articulated_shape(ShapePose::contact(1));
  Options options = load_options(UNFOLD_SOURCE_DIR "/configs/default.yaml");
  options.tet_shape = "contact";
  const PreparedMesh quick = prepare_mesh(crossed, options);
  EXPECT_TRUE(quick.tets_deferred);
  EXPECT_GT(quick.tet_report.contact_face_pairs, 0);
  const PreparedMesh with_tets = prepare_mesh(crossed, paper_options());
  ASSERT_GT(with_tets.tets.T.rows(), 0);
  const UnfoldResult a = unfold_prepared(quick, options);
  const UnfoldResult b = unfold_prepared(with_tets, options);
  EXPECT_EQ(a.tet_report.shape, "unfolded");
  EXPECT_EQ(b.tet_report.shape, "unfolded");
  EXPECT_FALSE(a.tet_report.contact_bridge) << "not checked";
  EXPECT_TRUE(b.tet_report.contact_bridge);
  ASSERT_EQ(a.tets.T, b.tets.T);
  EXPECT_LT((a.canonical.V - b.canonical.V).cwiseAbs().maxCoeff(),
            1e-6 * rms_radius(a.canonical.V));
}

// Shape auto: the unfolded shape's tets without any contact, the input's
// where no surface solve makes an unfolded shape (LSMDS, the volume domain)
// or the route conforming asks for TetGen's; contact: the input's tets where
// none bridges a contact.
TEST(PipelinePose, ShapeAutoTakesTheUnfoldedShapesTetsWhereThereIsASurfaceSolve) {
  // Resolution 32: which tets a config takes does not depend on it (64: 3.5x the time).
  const SurfaceMesh rest = make_articulated_shape(ShapePose::preset(0), 32);
  const Options options = load_options(UNFOLD_SOURCE_DIR "/configs/default.yaml");
  ASSERT_EQ(options.tet_shape, "auto");
  const PreparedMesh prepared = prepare_mesh(rest, options);
  EXPECT_TRUE(prepared.tets_deferred);
  EXPECT_EQ(unfold_prepared(prepared, options).tet_report.shape, "unfolded");
  Options lsmds = options;
  lsmds.method = "lsmds";
  Options volume = options;
  volume.domain = "volume";
  Options conforming = options;
  conforming.tet.route = "conforming";
  Options contact = options;
  contact.tet_shape = "contact";
  for (const Options& input_tets : {lsmds, volume, conforming, contact}) {
    const PreparedMesh with_tets = prepare_mesh(rest, input_tets);
    EXPECT_FALSE(with_tets.tets_deferred);
    const UnfoldResult r = unfold_prepared(with_tets, input_tets);
    EXPECT_EQ(r.tet_report.shape, "input") << input_tets.method << ", " << input_tets.domain;
    EXPECT_FALSE(r.tet_report.contact_bridge);
  }
}

TEST(PipelineSurfaceDomain, UnfoldsTheSurfaceAndPlacesTheInterior) {
  const SurfaceMesh a = make_articulated_shape(ShapePose::preset(0));
  Options surface;
  surface.domain = "surface";
  surface.tet_shape = "input";
  // The placement's own result: with the soft joints' filter the pose pull
  // (integrate_rotation_field_test) inverts one tet of this coarse shape.
  surface.integrate.pose_pull = 0;
  const UnfoldResult r = unfold_surface(a, surface);
  ASSERT_GT(r.tets.V.rows(), r.tets.num_surface_vertices) << "the demo shape has interior vertices";
  EXPECT_EQ(r.canonical.V.rows(), a.V.rows());
  EXPECT_TRUE(r.tet_canonical.allFinite());
  EXPECT_TRUE(r.cascade.reached_band);
  EXPECT_LE(r.cascade.edge_ratio, 1.05);
  // The interior is where ARAP puts it: not left at its rest place, no tet inverted.
  const Eigen::MatrixX3d interior = r.tet_canonical.bottomRows(r.tets.V.rows() - a.V.rows());
  EXPECT_GT(rms_radius(r.canonical.V), 1.05 * rms_radius(a.V));
  EXPECT_GT(rms_radius(interior), 1.05 * rms_radius(r.tets.V.bottomRows(interior.rows())));
  EXPECT_EQ(r.metrics.inverted_tets, 0);
  EXPECT_LT(r.metrics.E_rig, 1.5);
}

// soften.epsilon ends the second (soft joints') solve: looser, it stops sooner.
TEST(PipelineSoftJoints, TheSecondSolveEndsAtItsOwnEpsilon) {
  const SurfaceMesh a = make_articulated_shape(ShapePose::preset(1));
  Options tight;
  tight.soften.epsilon = 0;  // cascade.epsilon, 1e-7
  Options loose = tight;
  loose.soften.epsilon = 1e-4;
  const UnfoldResult t = unfold_surface(a, tight), l = unfold_surface(a, loose);
  EXPECT_GE(l.cascade.iterations, 1);
  EXPECT_LT(l.cascade.iterations, t.cascade.iterations);
}

TEST(PipelineInput, RefusesAnOpenSurface) {
  SurfaceMesh open = test::octahedron();
  open.faces.pop_back();
  try {
    const Options defaults;
    unfold_surface(open, defaults);
    FAIL() << "an open surface was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("open"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unfold
