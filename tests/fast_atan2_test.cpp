#include "geometry/fast_atan2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace unfold {
namespace {

// Over many magnitudes and every octant, and at the octant boundaries, where
// the reduction switches branch.
TEST(FastAtan2, WithinItsBoundOfStdAtan2) {
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal;
  double worst = 0;
  for (int k = 0; k < 2000000; ++k) {
    const double y = normal(random) * std::exp(4 * normal(random));
    const double x = normal(random) * std::exp(4 * normal(random));
    worst = std::max(worst, std::abs(fast_atan2(y, x) - std::atan2(y, x)));
  }
  for (double y : {1.0, -1.0, 1e-300, 3.0})
    for (double x : {1.0, -1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 1e300}) {
      worst = std::max(worst, std::abs(fast_atan2(y, x) - std::atan2(y, x)));
      worst = std::max(worst, std::abs(fast_atan2(x, y) - std::atan2(x, y)));
    }
  EXPECT_LE(worst, kFastAtan2Error);
  EXPECT_GT(worst, 0);  // an approximation: were it exact, the bound would say nothing
}

TEST(FastAtan2, TheFloatOverloadWithinItsBound) {
  std::mt19937_64 random(5);
  std::normal_distribution<float> normal;
  double worst = 0;
  for (int k = 0; k < 2000000; ++k) {
    const float y = normal(random) * std::exp(4 * normal(random));
    const float x = normal(random) * std::exp(4 * normal(random));
    worst = std::max(worst, std::abs(double(fast_atan2(y, x)) - std::atan2(double(y), double(x))));
  }
  for (float y : {1.0f, -1.0f, 3.0f})
    for (float x : {1.0f, -1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)}) {
      worst =
          std::max(worst, std::abs(double(fast_atan2(y, x)) - std::atan2(double(y), double(x))));
      worst =
          std::max(worst, std::abs(double(fast_atan2(x, y)) - std::atan2(double(x), double(y))));
    }
  EXPECT_LE(worst, kFastAtan2FloatError);
  for (float y : {0.0f, -0.0f, 2.0f, -2.0f})
    for (float x : {0.0f, -0.0f, 2.0f, -2.0f}) {
      if (y != 0 && x != 0) continue;
      EXPECT_EQ(fast_atan2(y, x), std::atan2(y, x)) << y << ", " << x;
      EXPECT_EQ(std::signbit(fast_atan2(y, x)), std::signbit(std::atan2(y, x))) << y << ", " << x;
    }
}

TEST(FastAtan2, SignedZerosAndAxesAsStdAtan2) {
  for (double y : {0.0, -0.0, 2.0, -2.0})
    for (double x : {0.0, -0.0, 2.0, -2.0}) {
      if (y != 0 && x != 0) continue;
      EXPECT_EQ(fast_atan2(y, x), std::atan2(y, x)) << y << ", " << x;
      EXPECT_EQ(std::signbit(fast_atan2(y, x)), std::signbit(std::atan2(y, x))) << y << ", " << x;
    }
}

}  // namespace
}  // namespace unfold
