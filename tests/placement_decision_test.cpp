// unfold_match's placement decision (issue 76): the curvature descriptor it
// compares (scale-free, orientation-free, constant on a sphere), the choice
// among the best rotation and its half turns (right on a shape without
// symmetry and sure of it, unsure exactly where a half turn is a symmetry),
// and on the shared scans pairs that the best fit alone places turned round,
// each placed right on its own.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "config/options.h"
#include "core/errors.h"
#include "geometry/point_tree.h"
#include "mesh/lumped_masses.h"
#include "mesh/mean_curvature_scales.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/read_vts.h"
#include "metrics/correspondence_error.h"
#include "pipeline/match_surfaces.h"
#include "test_meshes.h"

namespace unfold {
namespace {

TEST(MeanCurvatureScales, ConstantOnASphereWhateverItsSizeAndOrientation) {
  const SurfaceMesh sphere = test::uv_sphere(30, 60);
  const Eigen::MatrixX3i F = triangulate_faces(sphere);
  const Eigen::MatrixXd D = mean_curvature_scales(sphere.V, F);
  ASSERT_EQ(D.rows(), sphere.V.rows());
  ASSERT_EQ(D.cols(), 4);
  // k1 + k2 = 2 / r on a sphere of radius r; times sqrt(4 pi r^2): 4 sqrt(pi), at
  // every scale (the uv sphere's poles, where its triangles are slivers, least so).
  const double expected = 4 * std::sqrt(M_PI);
  for (Eigen::Index k = 0; k < D.cols(); ++k) {
    EXPECT_NEAR(D.col(k).mean(), expected, 0.02 * expected) << "scale " << k;
    EXPECT_LT((D.col(k).array() - expected).abs().mean(), 0.03 * expected) << "scale " << k;
    EXPECT_LT((D.col(k).array() - expected).abs().maxCoeff(), 0.25 * expected) << "scale " << k;
  }
  // Three times the size, and the triangles facing inwards: the same values.
  Eigen::MatrixX3i reversed = F;
  reversed.col(1).swap(reversed.col(2));
  const Eigen::MatrixXd big = mean_curvature_scales(3 * sphere.V, reversed);
  EXPECT_LT((big - D).cwiseAbs().maxCoeff(), 1e-6 * expected);
  EXPECT_THROW(mean_curvature_scales(sphere.V, F, {}), UsageError);
  EXPECT_THROW(mean_curvature_scales(sphere.V, F, {0.01, -1}), UsageError);
}

TEST(MeanCurvatureScales, SmoothingSpreadsABumpOverItsScale) {
  // A bump on a sphere: the finest scale sees it sharp, the coarsest spread
  // out (lower peak, the same mean over the surface: the heat step keeps
  // the integral).
  SurfaceMesh blob = test::uv_sphere(40, 80);
  for (Eigen::Index i = 0; i < blob.V.rows(); ++i) {
    const Eigen::Vector3d u = blob.V.row(i).normalized();
    blob.V.row(i) = ((1 + 0.4 * std::exp(-(u - Eigen::Vector3d::UnitX()).squaredNorm() / 0.02)) * u)
                        .transpose();
  }
  const Eigen::MatrixX3i F = triangulate_faces(blob);
  const Eigen::MatrixXd D = mean_curvature_scales(blob.V, F, {0.005, 0.2});
  EXPECT_GT(D.col(0).maxCoeff(), 1.5 * D.col(1).maxCoeff());
  const Eigen::VectorXd m = lumped_masses(blob.V, F);
  EXPECT_NEAR(m.dot(D.col(0)), m.dot(D.col(1)), 1e-6 * std::abs(m.dot(D.col(0))));
}

// The matcher's view of a rigid shape moved: its canonical form is itself
// (what the placement decision sees is the forms and the surfaces).
MatchShape rigid_shape(const SurfaceMesh& mesh, const Eigen::Matrix3d& R, const Options& options) {
  SurfaceMesh moved = mesh;
  moved.V = mesh.V * R.transpose();
  return match_shape_from_canonical(moved, moved, options);
}

double mean_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
  return (A - B).rowwise().norm().mean();
}

TEST(PlacementDecision, RightAndSureOnAShapeWithoutSymmetry) {
  const Options options;
  const SurfaceMesh source = test::chiral_blob(30, 60);
  const SurfaceMesh remeshed = test::chiral_blob(23, 47);
  const Eigen::Matrix3d R = test::random_rotation(11);
  const ShapeMatch match = match_shapes(rigid_shape(source, Eigen::Matrix3d::Identity(), options),
                                        rigid_shape(remeshed, R, options), options.match);
  EXPECT_GE(match.placements, 2) << match.decision;
  EXPECT_TRUE(match.sure) << match.decision;
  EXPECT_GT(match.placement_margin, 1.3) << match.decision;
  EXPECT_NE(match.decision.find("sure"), std::string::npos);
  // The chosen placement is the true rotation, and the map follows it.
  EXPECT_LT((match.rotation - R).norm(), 0.1) << match.decision;
  const Eigen::VectorXi truth = PointTree(remeshed.V).nearest_rows(source.V);
  EXPECT_LT(mean_distance(remeshed.V(match.map, Eigen::all), remeshed.V(truth, Eigen::all)), 0.05);
}

TEST(PlacementDecision, UnsureWhereAHalfTurnIsASymmetry) {
  // An ellipsoid with three different axes is the same shape turned half
  // round about any of them: nothing tells the placements apart, and the
  // decision says so.
  SurfaceMesh ellipsoid = test::uv_sphere(30, 60);
  ellipsoid.V = ellipsoid.V * Eigen::Vector3d(1.8, 1.0, 0.7).asDiagonal();
  const Options options;
  const ShapeMatch match =
      match_shapes(rigid_shape(ellipsoid, Eigen::Matrix3d::Identity(), options),
                   rigid_shape(ellipsoid, test::random_rotation(5), options), options.match);
  EXPECT_GE(match.placements, 2) << match.decision;
  EXPECT_FALSE(match.sure) << match.decision;
  EXPECT_LT(match.placement_margin, options.match.sure_margin) << match.decision;
  EXPECT_NE(match.decision.find("unsure"), std::string::npos);
  // The best fit alone compares nothing and claims nothing.
  Options residual = options;
  residual.match.placement = "residual";
  const ShapeMatch plain =
      match_shapes(rigid_shape(ellipsoid, Eigen::Matrix3d::Identity(), residual),
                   rigid_shape(ellipsoid, test::random_rotation(5), residual), residual.match);
  EXPECT_EQ(plain.placements, 0);
  EXPECT_TRUE(std::isinf(plain.placement_margin));
}

// A shared scan unfolded for matching, with its .vts template points.
struct Scan {
  std::string path;
  MatchShape shape;
  Eigen::VectorXi points;
};

Scan scan(const std::string& path, const Options& options) {
  const SurfaceMesh mesh = read_surface_mesh(path);
  Scan s{path, unfold_for_matching(mesh, options), {}};
  s.points = read_vts(path.substr(0, path.size() - 4) + ".vts", int(mesh.V.rows()));
  return s;
}

// The mean geodesic error over sqrt(area) of a map against the .vts truth.
double strict_error(const Scan& source, const Scan& target, const Eigen::VectorXi& map) {
  const std::vector<int> truth(target.points.data(), target.points.data() + target.points.size());
  const GeodesicTable table = geodesic_table(target.shape.V, target.shape.F, truth);
  return correspondence_errors(table, map, source.points, target.points).mean();
}

TEST(PlacementDecision, SharedScansTurnedRoundByTheBestFitArePlacedRightEachAlone) {
  // Pairs of two people whose best-fitting rotation puts one body's back onto
  // the other's front (strict error about 0.3); each decided on its own, no
  // collection.
  const std::string source_path = test::shared_data("faust_remeshed/tr_reg_006.off");
  const std::vector<std::string> targets = {test::shared_data("faust_people/tr_reg_049.off"),
                                            test::shared_data("faust_people/tr_reg_014.off")};
  if (source_path.empty() || targets[0].empty() || targets[1].empty())
    GTEST_SKIP() << "shared data absent: faust_remeshed, faust_people";
  const Options options;
  Options residual = options;
  residual.match.placement = "residual";
  const Scan source = scan(source_path, options);
  for (const std::string& path : targets) {
    const Scan target = scan(path, options);
    const ShapeMatch best_fit = match_shapes(source.shape, target.shape, residual.match);
    EXPECT_GT(strict_error(source, target, best_fit.map), 0.15)
        << path << ": " << best_fit.decision;
    const ShapeMatch match = match_shapes(source.shape, target.shape, options.match);
    EXPECT_LT(strict_error(source, target, match.map), 0.05) << path << ": " << match.decision;
    EXPECT_FALSE(match.mirrored) << match.decision;
    EXPECT_FALSE(match.from_collection);
  }
}

TEST(PlacementDecision, BadOptionsAreNamed) {
  MatchOptions o;
  o.placement = "best";
  EXPECT_THROW(validate_match_options(o), UsageError);
  o = MatchOptions();
  o.sure_margin = 0.5;
  EXPECT_THROW(validate_match_options(o), UsageError);
}

}  // namespace
}  // namespace unfold
