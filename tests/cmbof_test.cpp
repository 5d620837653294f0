// CM-BOF retrieval (Lian et al. 2013): the view sphere and its clock of
// rotations; hand-made histogram distances and clock matchings; k-means on
// separated clusters; depth images of a hand-made square; and the whole
// framework: zero with itself, near zero with a rotated, scaled copy, and two
// hand-made classes (animals, boxes) that it separates.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "core/errors.h"
#include "metrics/clock_matching.h"
#include "metrics/view_sphere.h"
#include "metrics/visual_vocabulary.h"
#include "pipeline/cmbof_vocabulary.h"
#include "pipeline/retrieval_descriptors.h"
#include "render/depth_image.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

TEST(ViewSphere, SubdividedOctahedronAndItsTwentyFourRotations) {
  for (const auto& [level, count] : {std::pair{0, 6}, {1, 18}, {2, 66}}) {
    const Eigen::MatrixX3d d = view_sphere_directions(level);
    ASSERT_EQ(d.rows(), count);
    EXPECT_LT((d.rowwise().norm().array() - 1).abs().maxCoeff(), 1e-12);
    const auto rotations = view_sphere_rotations(d);
    ASSERT_EQ(rotations.size(), 24u);
    std::vector<int> identity(static_cast<size_t>(count));
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(rotations[0], identity);
    std::set<std::vector<int>> distinct;
    for (const auto& p : rotations) {
      EXPECT_EQ(std::set<int>(p.begin(), p.end()).size(), size_t(count)) << "a bijection";
      distinct.insert(p);
    }
    EXPECT_EQ(distinct.size(), 24u);
  }
  EXPECT_THROW(view_sphere_directions(4), UsageError);
  Eigen::MatrixX3d tilted = view_sphere_directions(0);
  tilted.row(0) = Eigen::RowVector3d(1, 1, 0).normalized();
  EXPECT_THROW(view_sphere_rotations(tilted), UsageError);
}

TEST(ClockMatching, HandMadeHistogramsAndViews) {
  const WordHistogram a = {{1, 2}, {3, 1}}, b = {{1, 1}, {2, 2}};
  // Totals 3 and 3, common min(2, 1) = 1.
  EXPECT_DOUBLE_EQ(histogram_distance(a, b), 1 - 1.0 / 3);
  EXPECT_DOUBLE_EQ(histogram_distance(a, a), 0);
  EXPECT_DOUBLE_EQ(histogram_distance({}, {}), 0);
  EXPECT_DOUBLE_EQ(histogram_distance(a, {}), 1);
  EXPECT_DOUBLE_EQ(histogram_distance({{0, 4}}, {{0, 1}}), 0.75);
  // Six views, each its own word; b is a seen through the 7th rotation: the
  // clock finds it (0), while matching view to view costs 1 per moved view.
  const auto rotations = view_sphere_rotations(view_sphere_directions(0));
  std::vector<WordHistogram> views(6), turned(6);
  for (int v = 0; v < 6; ++v) views[size_t(v)] = {{v, 1}};
  for (int v = 0; v < 6; ++v) turned[size_t(rotations[7][size_t(v)])] = views[size_t(v)];
  EXPECT_DOUBLE_EQ(clock_matching_dissimilarity(views, turned, rotations), 0);
  int moved = 0;
  for (int v = 0; v < 6; ++v) moved += rotations[7][size_t(v)] != v;
  EXPECT_GT(moved, 0);
  EXPECT_DOUBLE_EQ(clock_matching_dissimilarity(views, turned, {rotations[0]}), moved);
  EXPECT_THROW(clock_matching_dissimilarity(views, {views[0]}, rotations), UsageError);
}

TEST(VisualVocabulary, KMeansFindsSeparatedClustersDeterministically) {
  // Three tight clusters of 20 points in 128 dimensions.
  Eigen::MatrixXf features(60, 128);
  for (int i = 0; i < 60; ++i)
    for (int k = 0; k < 128; ++k)
      features(i, k) = float(100 * (i % 3 == k % 3) + (i * 7 + k * 13) % 5);
  const Eigen::MatrixXf words = learn_vocabulary(features, 3, 10, 1);
  ASSERT_EQ(words.rows(), 3);
  EXPECT_EQ(learn_vocabulary(features, 3, 10, 1), words);
  const Eigen::VectorXi nearest = nearest_words(words, features);
  for (int i = 3; i < 60; ++i) EXPECT_EQ(nearest[i], nearest[i % 3]) << i;
  EXPECT_EQ(std::set<int>(nearest.data(), nearest.data() + 60).size(), 3u);
  // Each centre is its cluster's mean.
  for (int c = 0; c < 3; ++c) {
    Eigen::RowVectorXf mean = Eigen::RowVectorXf::Zero(128);
    for (int i = c; i < 60; i += 3) mean += features.row(i) / 20;
    EXPECT_LT((words.row(nearest[c]) - mean).cwiseAbs().maxCoeff(), 1e-4);
  }
  // Rows 0-3 are of clusters 0, 1, 2, 0.
  const std::map<int, int> counts = {{nearest[0], 2}, {nearest[1], 1}, {nearest[2], 1}};
  EXPECT_EQ(word_histogram(words, features.topRows(4)),
            WordHistogram(counts.begin(), counts.end()));
  EXPECT_EQ(learn_vocabulary(features, 100, 2, 1).rows(), 60) << "at most one word per feature";
  EXPECT_THROW(learn_vocabulary(Eigen::MatrixXf(0, 128), 3, 10, 1), UsageError);
}

TEST(DepthImage, ASquareFacingTheViewer) {
  // The square x = 0.5, |y|, |z| <= 0.5 seen from +x: 1 - 0.5 = 0.5 from the
  // plane, grey 255 (1 - 0.25); the square covers the image's middle half.
  Eigen::MatrixX3d V(4, 3);
  V << 0.5, -0.5, -0.5, 0.5, 0.5, -0.5, 0.5, 0.5, 0.5, 0.5, -0.5, 0.5;
  Eigen::MatrixX3i F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  const GrayImage image = depth_image(V, F, Eigen::Vector3d::UnitX(), 64);
  ASSERT_EQ(image.size, 64);
  const auto at = [&](int x, int y) { return int(image.pixels[size_t(y) * 64 + size_t(x)]); };
  EXPECT_EQ(at(32, 32), 191);
  EXPECT_EQ(at(17, 17), 191);
  EXPECT_EQ(at(46, 46), 191);
  EXPECT_EQ(at(5, 5), 0);
  EXPECT_EQ(at(60, 32), 0);
  // Seen from -x the square is 1.5 from the plane: 255 (1 - 0.75), darker.
  EXPECT_EQ(depth_image(V, F, -Eigen::Vector3d::UnitX(), 64).pixels[32 * 64 + 32],
            std::uint8_t(64));
  EXPECT_THROW(depth_image(V, F, Eigen::Vector3d::UnitX(), 4), UsageError);
}

// A box with sides (a, b, c), centred at the origin.
SurfaceMesh box(double a, double b, double c) {
  SurfaceMesh s = test::cube();
  s.V = (s.V.rowwise() - Eigen::RowVector3d(0.5, 0.5, 0.5)).array().rowwise() *
        Eigen::RowVector3d(a, b, c).array();
  return s;
}

TEST(Cmbof, InvariantToPoseNormalisationAndSeparatesTwoClasses) {
  RetrievalOptions options;
  options.cmbof.image_size = 128, options.cmbof.words = 64;
  std::vector<SurfaceMesh> shapes = {make_articulated_shape(ShapePose::rest(), 24),
                                     make_articulated_shape(ShapePose::preset(0), 24),
                                     make_articulated_shape(ShapePose::preset(1), 24),
                                     box(1, 0.7, 0.4),
                                     box(1, 0.6, 0.45),
                                     box(1, 0.75, 0.35)};
  // A copy of the first animal turned, scaled and moved.
  shapes.push_back({((3.5 * shapes[0].V) * test::random_rotation(5).transpose()).rowwise() +
                        Eigen::RowVector3d(1, -2, 4),
                    shapes[0].faces});
  std::vector<RetrievalDescriptor> d;
  std::vector<const CmbofFeatures*> features;
  for (const SurfaceMesh& s : shapes) d.push_back(retrieval_descriptor(s, options));
  for (const auto& descriptor : d) features.push_back(&descriptor.cmbof);
  const Eigen::MatrixXf vocabulary = cmbof_vocabulary(features, options.cmbof);
  for (auto& descriptor : d)
    descriptor.cmbof_histograms = cmbof_histograms(descriptor.cmbof, vocabulary);
  const auto D = [&](size_t i, size_t j) {
    return framework_dissimilarity(RetrievalFramework::cmbof, d[i], d[j], options);
  };
  EXPECT_EQ(D(0, 0), 0);
  EXPECT_EQ(D(4, 4), 0);
  double between = INFINITY, within = 0;  // animals 0-2, boxes 3-5
  for (size_t i = 0; i < 6; ++i)
    for (size_t j = i + 1; j < 6; ++j)
      if ((i < 3) == (j < 3))
        within = std::max(within, D(i, j));
      else
        between = std::min(between, D(i, j));
  EXPECT_LT(within, between) << "every pair of a class nearer than any pair across";
  // The turned, scaled copy is oriented like its original up to the clock's
  // rotations, but its depth images are not the same pixels (a view's in-plane
  // turn is fixed by its direction alone, so matched views can be turned
  // against each other by a non-right angle), and SIFT does not find quite the
  // same features: the distance is not 0, but well under the other poses'.
  EXPECT_LT(D(0, 6), 0.5 * std::min(D(0, 1), D(0, 2))) << "the copy is near its original";
  RetrievalDescriptor bare = d[0];
  bare.cmbof_histograms.clear();
  EXPECT_THROW(framework_dissimilarity(RetrievalFramework::cmbof, bare, d[1], options), UsageError);
}

}  // namespace
}  // namespace unfold
