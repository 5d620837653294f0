#include "geometry/fast_atan2.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>

namespace unfold {
namespace {

// The largest |fast_atan2 - std::atan2| (in double) over many magnitudes and
// every octant, and at the octant boundaries `ys` x `xs` (both ways round),
// where the reduction switches branch.
template <typename Real>
double worst_error(uint64_t seed, std::initializer_list<Real> ys, std::initializer_list<Real> xs) {
  std::mt19937_64 random(seed);
  std::normal_distribution<Real> normal;
  double worst = 0;
  const auto error = [](Real y, Real x) {
    return std::abs(double(fast_atan2(y, x)) - std::atan2(double(y), double(x)));
  };
  for (int k = 0; k < 2000000; ++k) {
    const Real y = normal(random) * std::exp(4 * normal(random));
    const Real x = normal(random) * std::exp(4 * normal(random));
    worst = std::max(worst, error(y, x));
  }
  for (Real y : ys)
    for (Real x : xs) worst = std::max({worst, error(y, x), error(x, y)});
  return worst;
}

// (+-0, +-0) and the axes exactly as std::atan2, signs of zero included.
template <typename Real>
void expect_signed_zeros_and_axes_as_std_atan2() {
  for (Real y : {Real(0), -Real(0), Real(2), -Real(2)})
    for (Real x : {Real(0), -Real(0), Real(2), -Real(2)}) {
      if (y != 0 && x != 0) continue;
      EXPECT_EQ(fast_atan2(y, x), std::atan2(y, x)) << y << ", " << x;
      EXPECT_EQ(std::signbit(fast_atan2(y, x)), std::signbit(std::atan2(y, x))) << y << ", " << x;
    }
}

TEST(FastAtan2, WithinItsBoundOfStdAtan2) {
  const double worst =
      worst_error<double>(3, {1.0, -1.0, 1e-300, 3.0},
                          {1.0, -1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 1e300});
  EXPECT_LE(worst, kFastAtan2Error);
  EXPECT_GT(worst, 0);  // an approximation: were it exact, the bound would say nothing
}

TEST(FastAtan2, TheFloatOverloadWithinItsBound) {
  EXPECT_LE(
      worst_error<float>(5, {1.0f, -1.0f, 3.0f},
                         {1.0f, -1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)}),
      kFastAtan2FloatError);
  expect_signed_zeros_and_axes_as_std_atan2<float>();
}

TEST(FastAtan2, SignedZerosAndAxesAsStdAtan2) {
  expect_signed_zeros_and_axes_as_std_atan2<double>();
}

}  // namespace
}  // namespace unfold
