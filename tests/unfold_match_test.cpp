// Dense correspondence from canonical forms (issue 46, unfold_match): the
// pieces (nearest points, the Laplace-Beltrami basis, the error measure), a
// shape mapped onto a rigidly moved, remeshed copy of itself, a mirrored copy
// detected as mirrored, and the command line's bad inputs (a missing shape, an
// unwritable map): one-line errors, no partial map, the other pairs done. The
// shapes are small generated ones without mirror symmetry (chiral_blob).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "config/options.h"
#include "geometry/point_tree.h"
#include "mesh/write_surface_mesh.h"
#include "metrics/correspondence_error.h"
#include "pipeline/match_surfaces.h"
#include "run_app.h"
#include "solvers/laplace_beltrami_basis.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

double surface_area(const SurfaceMesh& mesh) {
  const Eigen::MatrixX3i F = triangulate_faces(mesh);
  double area = 0;
  for (int f = 0; f < F.rows(); ++f)
    area += 0.5 * (mesh.V.row(F(f, 1)) - mesh.V.row(F(f, 0)))
                      .cross(mesh.V.row(F(f, 2)) - mesh.V.row(F(f, 0)))
                      .norm();
  return area;
}

// Mean distance between where the map sends each source vertex and where it
// should go (`truth`, in the unmoved target), over sqrt(area).
double mean_map_error(const SurfaceMesh& target, const Eigen::VectorXi& map,
                      const Eigen::VectorXi& truth) {
  double sum = 0;
  for (int i = 0; i < map.size(); ++i)
    sum += (target.V.row(map(i)) - target.V.row(truth(i))).norm();
  return sum / double(map.size()) / std::sqrt(surface_area(target));
}

SurfaceMesh moved(SurfaceMesh mesh, unsigned seed) {
  mesh.V = (mesh.V * test::random_rotation(seed).transpose()).rowwise() +
           Eigen::RowVector3d(0.4, -1.3, 2.0);
  return mesh;
}

// Its mirror image (y -> -y), faces reversed so that they still face outwards.
SurfaceMesh mirrored(SurfaceMesh mesh) {
  mesh.V.col(1) *= -1;
  for (auto& face : mesh.faces) std::reverse(face.begin(), face.end());
  return mesh;
}

TEST(UnfoldMatch, PointTreeFindsTheNearestPoint) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::MatrixX3d P(2000, 3), Q(300, 3);
  for (int i = 0; i < P.rows(); ++i) P.row(i) << uniform(random), uniform(random), uniform(random);
  for (int i = 0; i < Q.rows(); ++i) Q.row(i) << uniform(random), uniform(random), uniform(random);
  const PointTree tree(P);
  const Eigen::VectorXi found = tree.nearest_rows(Q);
  for (int q = 0; q < Q.rows(); ++q) {
    int best;
    (P.rowwise() - Q.row(q)).rowwise().squaredNorm().minCoeff(&best);
    ASSERT_EQ(found(q), best) << "query " << q;
  }
}

TEST(UnfoldMatch, LaplaceBeltramiBasisOfTheSphere) {
  // The unit sphere's eigenvalues are l (l + 1) with multiplicity 2 l + 1.
  const SurfaceMesh sphere = test::uv_sphere(40, 80);
  const LaplaceBeltramiBasis basis = laplace_beltrami_basis(sphere.V, triangulate_faces(sphere), 9);
  EXPECT_NEAR(basis.values(0), 0, 1e-6);
  for (int k = 1; k <= 3; ++k) EXPECT_NEAR(basis.values(k), 2, 0.05) << k;
  for (int k = 4; k <= 8; ++k) EXPECT_NEAR(basis.values(k), 6, 0.15) << k;
  const Eigen::MatrixXd gram = basis.phi.transpose() * basis.masses.asDiagonal() * basis.phi;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(9, 9)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(UnfoldMatch, ErrorsAreGeodesicOverSqrtAreaAndForgiveTheMirror) {
  const SurfaceMesh sphere = test::uv_sphere(20, 40);
  const Eigen::MatrixX3i F = triangulate_faces(sphere);
  const int n = int(sphere.V.rows());
  const Eigen::VectorXi identity = Eigen::VectorXi::LinSpaced(n, 0, n - 1);
  // Each vertex's mirror image across the plane y = 0.
  Eigen::MatrixX3d reflected = sphere.V;
  reflected.col(1) *= -1;
  const Eigen::VectorXi mirror = PointTree(sphere.V).nearest_rows(reflected);
  std::vector<int> all(identity.data(), identity.data() + n);
  const GeodesicTable table = geodesic_table(sphere.V, F, all);
  EXPECT_EQ(correspondence_errors(table, identity, identity, identity).maxCoeff(), 0);
  const Eigen::VectorXd flipped = correspondence_errors(table, mirror, identity, identity);
  // Off the mirror plane, a flip is far: up to half a great circle (pi) over sqrt(4 pi).
  EXPECT_GT(flipped.mean(), 0.15);
  EXPECT_LT(flipped.maxCoeff(), 1.05 * M_PI / std::sqrt(4 * M_PI));
  EXPECT_LT(correspondence_errors(table, mirror, identity, identity, mirror).maxCoeff(), 1e-6);
}

TEST(UnfoldMatch, RigidlyMovedRemeshedCopyIsNearlyExact) {
  const SurfaceMesh source = test::chiral_blob(30, 60);
  const SurfaceMesh remeshed = test::chiral_blob(23, 47);
  ASSERT_NE(source.V.rows(), remeshed.V.rows());
  const ShapeMatch match = match_surfaces(source, moved(remeshed, 7), Options());
  ASSERT_EQ(match.map.size(), source.V.rows());
  // The truth: the remeshed copy's vertex nearest to each source vertex.
  const Eigen::VectorXi truth = PointTree(remeshed.V).nearest_rows(source.V);
  const double error = mean_map_error(remeshed, match.map, truth);
  EXPECT_LT(error, 0.02) << match.decision;
  EXPECT_FALSE(match.mirrored) << match.decision;
}

TEST(UnfoldMatch, MirroredCopyIsDetectedAsMirrored) {
  const SurfaceMesh blob = test::chiral_blob(24, 48);
  // The squared spread's canonical form (configs/squared_spread.yaml): the
  // default's spread by distances splays this small blob nearly symmetric, so
  // its mirror image fits only 0.68x the rotation, inside the margin (ambiguous,
  // the rotation kept). On the shared scans the default's mirror decisions are
  // as good as before (docs/results/correspondence.md).
  Options options;
  options.energy.stretch_weight = 1;
  options.energy.stretch_distance = 0;
  options.energy.stretch_mass_power = 1;
  const MatchShape source = unfold_for_matching(blob, options);
  const MatchShape mirror = unfold_for_matching(moved(mirrored(blob), 3), options);
  const ShapeMatch match = match_shapes(source, mirror, options.match);
  EXPECT_TRUE(match.mirrored) << match.decision;
  EXPECT_FALSE(match.ambiguous) << match.decision;
  const int n = int(blob.V.rows());
  const Eigen::VectorXi identity = Eigen::VectorXi::LinSpaced(n, 0, n - 1);
  EXPECT_LT(mean_map_error(blob, match.map, identity), 0.02) << match.decision;
  // The same shape moved, not mirrored: a rotation, clearly.
  SurfaceMesh canonical = blob;
  canonical.V = source.canonical;
  const MatchShape copy = match_shape_from_canonical(moved(blob, 4), moved(canonical, 4), options);
  const ShapeMatch straight = match_shapes(source, copy, options.match);
  EXPECT_FALSE(straight.mirrored) << straight.decision;
  EXPECT_FALSE(straight.ambiguous) << straight.decision;
  EXPECT_LT(mean_map_error(blob, straight.map, identity), 0.02) << straight.decision;
}

TEST(UnfoldMatch, RotationSeedDecidesThePlacement) {
  // What unfold_match --pairs does with a pair the collection corrects: the
  // rotation placement refined from the seed, whatever fits best on its own.
  const SurfaceMesh blob = test::chiral_blob(24, 48);
  const Options options;
  const MatchShape source = unfold_for_matching(blob, options);
  SurfaceMesh canonical = blob;
  canonical.V = source.canonical;
  const MatchShape copy = match_shape_from_canonical(moved(blob, 4), moved(canonical, 4), options);
  const int n = int(blob.V.rows());
  const Eigen::VectorXi identity = Eigen::VectorXi::LinSpaced(n, 0, n - 1);
  const Eigen::Matrix3d truth = test::random_rotation(4);
  const ShapeMatch seeded = match_shapes(source, copy, options.match, &truth);
  EXPECT_TRUE(seeded.from_collection);
  EXPECT_NE(seeded.decision.find("placed by the collection"), std::string::npos);
  EXPECT_LT(mean_map_error(blob, seeded.map, identity), 0.02) << seeded.decision;
  // A seed turned round the long axis: the map follows it, far from the truth.
  const Eigen::Matrix3d turned =
      truth * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  MatchOptions rigid = options.match;
  rigid.refine = "none";
  const ShapeMatch wrong = match_shapes(source, copy, rigid, &turned);
  EXPECT_TRUE(wrong.from_collection);
  EXPECT_GT(mean_map_error(blob, wrong.map, identity), 0.1) << wrong.decision;
  EXPECT_FALSE(match_shapes(source, copy, rigid).from_collection);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(UnfoldMatch, BatchReportsBadPairsAndGoesOn) {
  test::TempDir dir;
  const std::string in = dir.file("in"), out = dir.file("out");
  std::filesystem::create_directories(in);
  std::filesystem::create_directories(out);
  const SurfaceMesh a = test::chiral_blob(16, 32);
  write_surface_mesh(in + "/a.off", a);
  write_surface_mesh(in + "/b.off", moved(test::chiral_blob(14, 30), 2));
  // b__a.map cannot be written: a directory is in the way.
  std::filesystem::create_directories(out + "/b__a.map");
  test::write_bytes(dir.file("pairs.txt"), "# source target\na b\na missing\nb a\n");
  const test::AppRun r = test::run_app(
      "unfold_match", "--pairs " + dir.file("pairs.txt") + " --input_dir " + in + " --output_dir " +
                          out + " --match_refine none --progress=false");
  EXPECT_EQ(r.exit_code, 3) << r.err;  // the first failure's class: a missing input
  const std::vector<std::string> err = lines_of(r.err);
  int missing = 0, unwritable = 0;
  for (const std::string& line : err) {
    if (line.find("unfold_match: error: pair a missing: shape 'missing' not found") == 0) ++missing;
    if (line.find("unfold_match: error: pair b a: ") == 0 &&
        line.find("b__a.map") != std::string::npos)
      ++unwritable;
  }
  EXPECT_EQ(missing, 1) << r.err;
  EXPECT_EQ(unwritable, 1) << r.err;
  EXPECT_NE(r.err.find("2 of 3 pairs failed"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("1 of 3 pairs matched"), std::string::npos) << r.out;
  // The good pair's map: one id per source vertex, all in range; no other map.
  std::ifstream map(out + "/a__b.map");
  int count = 0, id;
  while (map >> id) {
    EXPECT_GE(id, 0);
    ++count;
  }
  EXPECT_EQ(count, a.V.rows());
  EXPECT_FALSE(test::file_exists(out + "/a__missing.map"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1) << "a failed pair left a (partial) file";
}

TEST(UnfoldMatch, OnePairBadInputsAreOneLineErrorsWithoutAMap) {
  test::TempDir dir;
  write_surface_mesh(dir.file("a.off"), test::chiral_blob(16, 32));
  const std::string a = dir.file("a.off");
  struct Case {
    std::string args;
    int code;
    std::string words;
    std::string output;
  };
  const Case cases[] = {
      {"--source " + a + " --target " + dir.file("none.off"), 3, "none.off", dir.file("m.map")},
      {"--source " + a + " --target " + a, 5, "no_such_dir", dir.file("no_such_dir/m.map")},
      {"--source " + a, 2, "--target", dir.file("m.map")},
      {"--source " + a + " --target " + a + " --match_mirror sometimes", 2, "match.mirror",
       dir.file("m.map")},
  };
  for (const Case& c : cases) {
    const test::AppRun r = test::run_app("unfold_match", c.args + " --output " + c.output);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("unfold_match: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.words), std::string::npos) << r.err;
    EXPECT_FALSE(test::file_exists(c.output)) << c.args;
  }
  test::write_bytes(dir.file("pairs.txt"), "a b c\n");
  const test::AppRun r =
      test::run_app("unfold_match", "--pairs " + dir.file("pairs.txt") + " --input_dir " +
                                        dir.file("") + " --output_dir " + dir.file("out"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("expected two shape names"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace unfold
