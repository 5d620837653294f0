// Retrieval: the benchmark measures on a hand-made matrix whose values are
// worked out by hand; rectilinearity and the ORT normalisation invariant to a
// rigid motion and a scale; silhouette pixels counted by hand and as the
// renderer draws them, and the orientation they choose where a bounding box
// would choose the other; the ORT dissimilarity's value on a hand-made pair;
// similarity blocks (every framework, CMBOF too) that assemble to the matrix
// computed in one go; the descriptors' exact round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/errors.h"
#include "metrics/ort_dissimilarity.h"
#include "metrics/pose_invariance.h"
#include "metrics/rectilinearity.h"
#include "metrics/retrieval_measures.h"
#include "metrics/silhouette_area.h"
#include "pipeline/cmbof_vocabulary.h"
#include "pipeline/similarity_blocks.h"
#include "render/rasterize.h"
#include "shapes/articulated_shape.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// Shapes 0, 1, 2 of class a, 3 and 4 of class b. Ranked lists (query left out):
//   0: 2a 3b 1a 4b    1: 3b 0a 2a 4b    2: 0a 1a 3b 4b
//   3: 1a 0a 2a 4b    4: 0a 1a 2a 3b
Eigen::MatrixXd hand_made_matrix() {
  Eigen::MatrixXd D(5, 5);
  D << 0, 3, 1, 2, 4,  //
      3, 0, 5, 1, 6,   //
      1, 5, 0, 7, 8,   //
      2, 1, 7, 0, 9,   //
      4, 6, 8, 9, 0;
  return D;
}

TEST(RetrievalMeasures, HandMadeMatrixGivesTheHandComputedValues) {
  const RetrievalMeasures m = retrieval_measures(hand_made_matrix(), {"a", "a", "a", "b", "b"});
  EXPECT_EQ(m.queries, 5);
  // Per query NN: 1 0 1 0 0; FT (R = 2, 2, 2, 1, 1): 1/2 1/2 1 0 0; ST: 1 1 1 0 0.
  EXPECT_DOUBLE_EQ(m.nn, 2.0 / 5);
  EXPECT_DOUBLE_EQ(m.first_tier, 2.0 / 5);
  EXPECT_DOUBLE_EQ(m.second_tier, 3.0 / 5);
  // E over 32 retrieved: class a finds 2 of 2 (P = 2/32, R = 1), class b 1 of 1.
  const double e_a = 2 * (2.0 / 32) / (2.0 / 32 + 1), e_b = 2 * (1.0 / 32) / (1.0 / 32 + 1);
  EXPECT_DOUBLE_EQ(m.e_measure, (3 * e_a + 2 * e_b) / 5);
  // DCG / ideal: queries 0 and 1 have relevant at ranks 1, 3 and 2, 3; query 2 is
  // ideal; queries 3 and 4 find their one relevant at rank 4 (1 / log2 4).
  const double dcg0 = (1 + 1 / std::log2(3.0)) / 2, dcg1 = (1 + 1 / std::log2(3.0)) / 2;
  EXPECT_NEAR(m.dcg, (dcg0 + dcg1 + 1 + 0.5 + 0.5) / 5, 1e-15);
  // Interpolated precision: query 0: 1 up to recall 1/2, then 2/3; query 1: 2/3;
  // query 2: 1; queries 3, 4: 1/4.
  ASSERT_EQ(m.precision.size(), size_t(kRecallLevels));
  EXPECT_NEAR(m.precision[0], (1 + 2.0 / 3 + 1 + 0.25 + 0.25) / 5, 1e-15);
  EXPECT_NEAR(m.precision[9], (1 + 2.0 / 3 + 1 + 0.25 + 0.25) / 5, 1e-15);  // recall 0.5
  EXPECT_NEAR(m.precision[10], (2.0 / 3 + 2.0 / 3 + 1 + 0.25 + 0.25) / 5, 1e-15);
  EXPECT_NEAR(m.precision[19], (2.0 / 3 + 2.0 / 3 + 1 + 0.25 + 0.25) / 5, 1e-15);
}

TEST(RetrievalMeasures, ASingletonClassIsNoQueryAndBadInputsThrow) {
  // A sixth shape alone in its class, far from all: the last of every list,
  // irrelevant to every query, so nothing changes.
  Eigen::MatrixXd D = Eigen::MatrixXd::Constant(6, 6, 100);
  D.topLeftCorner(5, 5) = hand_made_matrix();
  D(5, 5) = 0;
  const RetrievalMeasures with = retrieval_measures(D, {"a", "a", "a", "b", "b", "c"});
  const RetrievalMeasures without =
      retrieval_measures(hand_made_matrix(), {"a", "a", "a", "b", "b"});
  EXPECT_EQ(with.queries, 5);
  EXPECT_DOUBLE_EQ(with.nn, without.nn);
  EXPECT_DOUBLE_EQ(with.dcg, without.dcg);
  EXPECT_DOUBLE_EQ(with.e_measure, without.e_measure);
  EXPECT_EQ(with.precision, without.precision);
  EXPECT_THROW(retrieval_measures(hand_made_matrix(), {"a", "b", "c", "d", "e"}), UsageError);
  EXPECT_THROW(retrieval_measures(hand_made_matrix(), {"a", "a"}), UsageError);
  Eigen::MatrixXd nan = hand_made_matrix();
  nan(0, 1) = std::nan("");
  EXPECT_THROW(retrieval_measures(nan, {"a", "a", "a", "b", "b"}), UsageError);
}

TEST(Rectilinearity, ARotatedBoxIsFoundAxisAlignedAndASphereIsNot) {
  SurfaceMesh box = test::cube();
  box.V.col(0) *= 3;
  box.V.col(1) *= 2;
  const Eigen::MatrixX3i F = triangulate_faces(box);
  const Eigen::Matrix3d turn = test::random_rotation(3);
  const Eigen::MatrixX3d turned = box.V * turn.transpose();
  EXPECT_NEAR(rectilinearity(box.V, F, Eigen::Matrix3d::Identity()), 1, 1e-12);
  EXPECT_LT(rectilinearity(turned, F, Eigen::Matrix3d::Identity()), 0.9);
  EXPECT_NEAR(rectilinearity(turned, F, rectilinearity_orientation(turned, F)), 1, 1e-6);
  const SurfaceMesh sphere = test::uv_sphere(24, 32);
  const Eigen::MatrixX3i G = triangulate_faces(sphere);
  EXPECT_LT(rectilinearity(sphere.V, G, rectilinearity_orientation(sphere.V, G)), 0.3);
  // A zero-area mesh: one triangle on three coincident vertices.
  EXPECT_THROW(rectilinearity(Eigen::MatrixX3d::Zero(3, 3), Eigen::RowVector3i(0, 1, 2),
                              Eigen::Matrix3d::Identity()),
               UsageError);
}

TEST(Ort, TheNormalisedSampleIsInvariantToARigidMotionAndAScale) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 24);
  const Eigen::MatrixX3i F = triangulate_faces(shape);
  const Eigen::MatrixX3d moved =
      ((4.2 * shape.V) * test::random_rotation(11).transpose()).rowwise() +
      Eigen::RowVector3d(-2, 5, 1);
  const Eigen::MatrixX3d a = ort_sample(shape.V, F, 500), b = ort_sample(moved, F, 500);
  ASSERT_EQ(a.rows(), b.rows());
  // The same points, up to the orientation's cube ambiguity.
  double closest = INFINITY;
  for (const Eigen::Matrix3d& R : cube_rotations())
    closest = std::min(closest, (a * R.transpose() - b).cwiseAbs().maxCoeff());
  EXPECT_LT(closest, 1e-6);
  EXPECT_LT(ort_dissimilarity(a, b, 20), 1e-12);
  // Every vertex kept (in order): unit area, area centroid at the origin.
  const Eigen::MatrixX3d all = ort_sample(moved, F, int(shape.V.rows()));
  EXPECT_NEAR(surface_area(all, F), 1, 1e-12);
  Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d p = all.row(F(f, 0)), q = all.row(F(f, 1)), r = all.row(F(f, 2));
    centroid += 0.5 * (q - p).cross(r - p).norm() * (p + q + r) / 3;
  }
  EXPECT_LT(centroid.norm(), 1e-12);
  EXPECT_THROW(ort_sample(shape.V, F, 3), UsageError);
}

TEST(Silhouette, PixelsOfASquareByHandAndOfAShapeAsTheRendererDrawsThem) {
  // The square |x|, |y| <= 0.5 at z = 0.3: along z it covers the middle half of
  // the grid (pixel centres never lie on its edges), seen edge-on nothing.
  Eigen::MatrixX3d V(4, 3);
  V << -0.5, -0.5, 0.3, 0.5, -0.5, 0.3, 0.5, 0.5, 0.3, -0.5, 0.5, 0.3;
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  EXPECT_EQ(silhouette_pixels(V, F, 2, 256), 128 * 128);
  EXPECT_EQ(silhouette_pixels(V, F.rowwise().reverse(), 2, 256), 128 * 128) << "either winding";
  EXPECT_EQ(silhouette_pixels(V, F, 0, 256), 0);
  EXPECT_EQ(silhouette_pixels(V, F, 1, 256), 0);
  // Moved half out of the square [-1, 1]^2 in x and y: a quarter stays.
  const Eigen::MatrixX3d out = V.rowwise() + Eigen::RowVector3d(1, 1, 0);
  EXPECT_EQ(silhouette_pixels(out, F, 2, 256), 64 * 64);
  // A shape turned at random, in the unit ball: every axis view covers the
  // pixels render/'s rasterizer draws for the same projection.
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(2), 24);
  const Eigen::MatrixX3i G = triangulate_faces(shape);
  Eigen::MatrixX3d W = (shape.V.rowwise() - shape.V.colwise().mean()) * test::random_rotation(4);
  W /= W.rowwise().norm().maxCoeff();
  const int size = 96;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    Canvas canvas(size, size);
    for (Eigen::Index f = 0; f < G.rows(); ++f) {
      Eigen::Matrix3d xyz;
      for (int k = 0; k < 3; ++k)
        xyz.row(k) << (W(G(f, k), u) + 1) * size / 2, (W(G(f, k), v) + 1) * size / 2, 0;
      rasterize_triangle(xyz, Eigen::Matrix3f::Zero(), &canvas);
    }
    const long drawn = std::count_if(canvas.depth.begin(), canvas.depth.end(),
                                     [](double d) { return std::isfinite(d); });
    EXPECT_GT(drawn, size * size / 20) << axis;
    EXPECT_EQ(silhouette_pixels(W, G, axis, size), drawn) << axis;
  }
  EXPECT_THROW(silhouette_pixels(V, F, 3, 256), UsageError);
  EXPECT_THROW(silhouette_pixels(V, F, 0, 0), UsageError);
}

TEST(Ort, TheOrientationIsTheOneWithTheSmallerSilhouetteArea) {
  // Two 1 x 1 x 2 boxes, on the diagonal of the xy plane 2 apart: the principal
  // axes are the diagonals (u, v) and z, and the rectilinearity orientation is
  // the boxes' own axes. The diagonal frame has the smaller bounding box
  // (3 sqrt 2 x sqrt 2 x 2 = 12 against 3 x 3 x 2 = 18) but the larger
  // silhouettes (uv 2, vz 2 sqrt 2, uz 4 sqrt 2: 10.5 against 2 + 4 + 4 = 10),
  // so the orientation must be the boxes' own, up to a rotation of the cube.
  SurfaceMesh two = test::cube();
  two.V.col(2) *= 2;
  const Eigen::Index n = two.V.rows();
  two.V.conservativeResize(2 * n, 3);
  two.V.bottomRows(n) = two.V.topRows(n).rowwise() + Eigen::RowVector3d(2, 2, 0);
  for (size_t f = 0, faces = two.faces.size(); f < faces; ++f) {
    std::vector<int> face = two.faces[f];
    for (int& i : face) i += int(n);
    two.faces.push_back(face);
  }
  const Eigen::MatrixX3i F = triangulate_faces(two);
  const Eigen::MatrixX3d centred = two.V.rowwise() - Eigen::RowVector3d(1.5, 1.5, 1);
  const Eigen::Matrix3d diagonal = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).matrix();
  const Eigen::MatrixX3d in_diagonal = centred * diagonal.transpose();
  const auto box_volume = [](const Eigen::MatrixX3d& P) {
    return (P.colwise().maxCoeff() - P.colwise().minCoeff()).prod();
  };
  ASSERT_NEAR(box_volume(in_diagonal), 12, 1e-12);
  ASSERT_NEAR(box_volume(centred), 18, 1e-12);
  EXPECT_GT(axis_silhouette_pixels(in_diagonal, F), axis_silhouette_pixels(centred, F) * 1.03);
  // Turned at random (neither candidate is the input's frame), then oriented.
  const Eigen::Matrix3d turn = test::random_rotation(7);
  const Eigen::Matrix3d R = ort_orientation(centred * turn.transpose(), F) * turn;
  double nearest_cube_rotation = INFINITY;
  for (const Eigen::Matrix3d& C : cube_rotations())
    nearest_cube_rotation = std::min(nearest_cube_rotation, (R - C).cwiseAbs().maxCoeff());
  EXPECT_LT(nearest_cube_rotation, 1e-6);
}

TEST(Ort, HandMadePairHasItsKnownMeanSquaredError) {
  // The six axis points and the same at twice the size: every point is 1 from
  // its nearest, in every rotation of the cube and after ICP (the matched pairs
  // are already best aligned).
  Eigen::MatrixX3d A(6, 3);
  A << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  EXPECT_DOUBLE_EQ(mean_squared_point_error(A, 2 * A), 1);
  EXPECT_DOUBLE_EQ(ort_dissimilarity(A, 2 * A, 20), 1);
  // A box's corners against the same box turned a quarter about z: the cube
  // rotation undoes it exactly.
  Eigen::MatrixX3d box = test::cube().V.rowwise() - Eigen::RowVector3d(0.5, 0.5, 0.5);
  box.col(0) *= 3;
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).matrix();
  EXPECT_GT(mean_squared_point_error(box, box * quarter.transpose()), 1);
  EXPECT_NEAR(ort_dissimilarity(box, box * quarter.transpose(), 20), 0, 1e-24);
  // One corner moved by 0.5: squared error 0.25 from each side over 8 points.
  Eigen::MatrixX3d bumped = box;
  bumped(0, 2) -= 0.5;
  EXPECT_DOUBLE_EQ(mean_squared_point_error(box, bumped), 0.25 / 8);
  EXPECT_THROW(ort_dissimilarity(A, Eigen::MatrixX3d(0, 3), 20), UsageError);
}

// The vocabulary's cache key holds each shape's features' fingerprint: a shape
// unfolded again (--skip_existing) must not find the old vocabulary.
TEST(CmbofVocabulary, TheFeaturesFingerprintFollowsEveryByteAndViewBoundary) {
  CmbofOptions options;
  options.view_subdivisions = 0, options.image_size = 64;
  const SurfaceMesh s = make_articulated_shape(ShapePose::preset(0), 16);
  const CmbofFeatures a =
      cmbof_features(ort_normalise(s.V, triangulate_faces(s)), triangulate_faces(s), options);
  ASSERT_GT(a.descriptors.rows(), 2);
  CmbofFeatures b = a;
  EXPECT_EQ(features_fingerprint(a), features_fingerprint(b));
  b.descriptors(b.descriptors.rows() - 1, 127) ^= 1;
  EXPECT_NE(features_fingerprint(a), features_fingerprint(b));
  CmbofFeatures c = a;
  for (int& start : c.view_start)
    if (start > 0 && start < c.descriptors.rows()) {
      --start;
      break;
    }
  EXPECT_NE(features_fingerprint(a), features_fingerprint(c));
}

TEST(SimilarityBlocks, BlocksWrittenByShardsAssembleToTheOneGoMatrix) {
  std::vector<RetrievalDescriptor> d;
  std::vector<std::string> names;
  RetrievalOptions options{100, 5};
  options.cmbof.view_subdivisions = 1, options.cmbof.image_size = 128, options.cmbof.words = 32;
  std::vector<const CmbofFeatures*> features;
  for (int k = 0; k < 5; ++k) {
    const SurfaceMesh s = make_articulated_shape(ShapePose::preset(k % 3), 16);
    d.push_back(retrieval_descriptor({s.V * (1 + 0.1 * k), s.faces}, options));
    names.push_back("s" + std::to_string(k));
  }
  for (const auto& descriptor : d) features.push_back(&descriptor.cmbof);
  const Eigen::MatrixXf vocabulary = cmbof_vocabulary(features, options.cmbof);
  for (auto& descriptor : d)
    descriptor.cmbof_histograms = cmbof_histograms(descriptor.cmbof, vocabulary);
  const test::TempDir dir;
  const std::string blocks = dir.file("blocks");
  std::filesystem::create_directories(blocks);
  for (const RetrievalFramework f : kRetrievalFrameworks) {
    SCOPED_TRACE(framework_name(f));
    const std::string key = similarity_key(f, options, vocabulary_fingerprint(vocabulary));
    const Eigen::MatrixXd one_go = assemble_similarity(d, names, f, blocks, "none", key, options);
    EXPECT_EQ(one_go, one_go.transpose());
    EXPECT_EQ(one_go.diagonal(), Eigen::VectorXd::Zero(5));
    for (int i = 0; i < 3; ++i)
      write_similarity_block(
          blocks + "/m_" + std::string(framework_name(f)) + "." + std::to_string(i) + "-of-3.csv",
          similarity_block(d, f, i, 3, options), names, i, 3, key);
    Eigen::MatrixXd read = Eigen::MatrixXd::Constant(5, 5, NAN);
    int rows = 0;
    for (int i = 0; i < 3; ++i)
      rows += read_similarity_block(
          blocks + "/m_" + std::string(framework_name(f)) + "." + std::to_string(i) + "-of-3.csv",
          names, key, &read);
    EXPECT_EQ(rows, 5);
    for (int i = 0; i < 5; ++i)
      for (int j = i + 1; j < 5; ++j) EXPECT_EQ(read(i, j), one_go(i, j)) << i << "," << j;
    EXPECT_EQ(assemble_similarity(d, names, f, blocks, "m_" + std::string(framework_name(f)), key,
                                  options),
              one_go);
    // Another shape list or other options: the block is not used.
    std::vector<std::string> other = names;
    other[4] = "t";
    EXPECT_EQ(read_similarity_block(blocks + "/m_" + std::string(framework_name(f)) + ".0-of-3.csv",
                                    other, key, &read),
              0);
    EXPECT_EQ(read_similarity_block(blocks + "/m_" + std::string(framework_name(f)) + ".0-of-3.csv",
                                    names, key + "x", &read),
              0);
  }
}

TEST(SimilarityBlocks, DescriptorsRoundTripExactly) {
  const SurfaceMesh s = make_articulated_shape(ShapePose::preset(2), 16);
  RetrievalOptions options{300, 5};
  options.cmbof.view_subdivisions = 0, options.cmbof.image_size = 128;
  const RetrievalDescriptor d = retrieval_descriptor(s, options);
  ASSERT_EQ(d.cmbof.views(), 6);
  EXPECT_GT(d.cmbof.descriptors.rows(), 6);
  const test::TempDir dir;
  write_retrieval_descriptor(dir.file("d.txt"), d, options);
  const auto back = read_retrieval_descriptor(dir.file("d.txt"), options);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->icp, d.icp);
  EXPECT_EQ(back->ort, d.ort);
  EXPECT_EQ(back->cmbof.view_start, d.cmbof.view_start);
  EXPECT_EQ(back->cmbof.descriptors, d.cmbof.descriptors);
  EXPECT_FALSE(read_retrieval_descriptor(dir.file("d.txt"), RetrievalOptions{301, 5}));
  RetrievalOptions other = options;
  other.cmbof.words = 7;  // the features do not depend on the vocabulary
  EXPECT_TRUE(read_retrieval_descriptor(dir.file("d.txt"), other));
  other.cmbof.view_subdivisions = 1;
  EXPECT_FALSE(read_retrieval_descriptor(dir.file("d.txt"), other));
  EXPECT_FALSE(read_retrieval_descriptor(dir.file("missing.txt"), options));
}

}  // namespace
}  // namespace unfold
