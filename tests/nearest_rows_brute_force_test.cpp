// The spectral embedding's exact nearest neighbours (geometry/nearest_rows_brute_force.h):
// on every instruction set the processor has, the nearest row of random data at
// sizes that are not multiples of the scan's blocks, the first of equal rows,
// and the errors.
#include "geometry/nearest_rows_brute_force.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

#include "core/errors.h"

namespace unfold {
namespace {

// The least squared distance from query i to any database row, in double.
double least_distance(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& database, long i) {
  double least = std::numeric_limits<double>::infinity();
  for (long j = 0; j < database.rows(); ++j)
    least = std::min(
        least, (queries.row(i).cast<double>() - database.row(j).cast<double>()).squaredNorm());
  return least;
}

class NearestRowsBruteForce : public testing::TestWithParam<VectorInstructions> {
 protected:
  void SetUp() override {
    if (!supports(GetParam())) GTEST_SKIP() << "this processor lacks these instructions";
  }
};

TEST_P(NearestRowsBruteForce, FindsTheNearestRowAtAnySize) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uniform(-1, 1);
  for (const auto& [m, n, k] : {std::tuple{1, 1, 1},
                                {7, 3, 2},
                                {65, 33, 5},
                                {130, 600, 17},
                                {203, 1100, 80},
                                {9, 513, 0}}) {
    Eigen::MatrixXf queries(m, k), database(n, k);
    for (float& x : queries.reshaped()) x = uniform(random);
    for (float& x : database.reshaped()) x = uniform(random);
    const Eigen::VectorXi nearest = nearest_rows_brute_force(queries, database, GetParam());
    ASSERT_EQ(nearest.size(), m);
    for (long i = 0; i < m; ++i) {
      ASSERT_GE(nearest(i), 0);
      ASSERT_LT(nearest(i), n);
      const double found =
          (queries.row(i).cast<double>() - database.row(nearest(i)).cast<double>()).squaredNorm();
      // single precision: equal up to its rounding
      EXPECT_LE(found, least_distance(queries, database, i) + 1e-5 * (1 + k))
          << m << " x " << n << " x " << k << ", query " << i;
    }
  }
}

TEST_P(NearestRowsBruteForce, OfEqualRowsTheFirst) {
  // Every row repeated 40 times (more than a register block): the first copy.
  std::mt19937 random(9);
  std::uniform_real_distribution<float> uniform(-1, 1);
  const int distinct = 30, copies = 40, k = 12;
  Eigen::MatrixXf rows(distinct, k);
  for (float& x : rows.reshaped()) x = uniform(random);
  Eigen::MatrixXf database(distinct * copies, k);
  for (int c = 0; c < copies; ++c) database.middleRows(c * distinct, distinct) = rows;
  const Eigen::VectorXi nearest = nearest_rows_brute_force(rows, database, GetParam());
  for (int i = 0; i < distinct; ++i) EXPECT_EQ(nearest(i), i);
}

TEST_P(NearestRowsBruteForce, AgreesWithTheWidestInstructions) {
  std::mt19937 random(11);
  std::normal_distribution<float> normal;
  Eigen::MatrixXf queries(500, 40), database(700, 40);
  for (float& x : queries.reshaped()) x = normal(random);
  for (float& x : database.reshaped()) x = normal(random);
  const Eigen::VectorXi a = nearest_rows_brute_force(queries, database, GetParam());
  const Eigen::VectorXi b = nearest_rows_brute_force(queries, database);
  // the same rows but where two distances differ by rounding alone
  EXPECT_LE((a.array() != b.array()).count(), 2);
}

INSTANTIATE_TEST_SUITE_P(EachInstructionSet, NearestRowsBruteForce,
                         testing::Values(VectorInstructions::baseline, VectorInstructions::avx2,
                                         VectorInstructions::avx512),
                         [](const testing::TestParamInfo<VectorInstructions>& info) {
                           return std::string(info.param == VectorInstructions::baseline
                                                  ? "baseline"
                                              : info.param == VectorInstructions::avx2 ? "avx2"
                                                                                       : "avx512");
                         });

TEST(NearestRowsBruteForceErrors, WidthsThatDifferOrNoDatabase) {
  EXPECT_THROW(nearest_rows_brute_force(Eigen::MatrixXf::Zero(3, 4), Eigen::MatrixXf::Zero(5, 3)),
               UsageError);
  EXPECT_THROW(nearest_rows_brute_force(Eigen::MatrixXf::Zero(3, 4), Eigen::MatrixXf::Zero(0, 4)),
               UsageError);
  EXPECT_EQ(
      nearest_rows_brute_force(Eigen::MatrixXf::Zero(0, 4), Eigen::MatrixXf::Zero(2, 4)).size(), 0);
}

}  // namespace
}  // namespace unfold
