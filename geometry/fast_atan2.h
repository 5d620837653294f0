// atan2 without the libm call: the winding number's near field takes one per
// triangle, and libm's was a third of the robust route's carve.
#pragma once

#include <cmath>

namespace unfold {

/// The bound on |fast_atan2(y, x) - atan2(y, x)| that tests/fast_atan2_test.cpp checks.
constexpr double kFastAtan2Error = 1e-10;
/// The same for the float overload (its polynomial's 6e-8 and float's rounding).
constexpr double kFastAtan2FloatError = 5e-7;

/// atan2(y, x) to within kFastAtan2Error, for finite y and x; (+-0, +-0) gives
/// +-0 or +-pi as std::atan2 does. The octant reduction t = min(|x|, |y|) /
/// max(|x|, |y|) in [0, 1], then atan(t) = t p(t^2) with p of degree 11
/// interpolating atan(sqrt s) / sqrt s at 12 Chebyshev nodes on [0, 1] (error
/// 4e-11), evaluated in Estrin's scheme: a few independent multiply-adds deep,
/// where a Horner chain was no faster than libm.
inline double fast_atan2(double y, double x) {
  static constexpr double a[12] = {
      0.99999999992930244,  -0.33333331290885149,  0.19999901102156251,   -0.14283813257109715,
      0.11091922983234306,  -0.089741720766549321, 0.072282787413693456,  -0.053956688586216231,
      0.033826229014569734, -0.015828330421451632, 0.0047324874515955644, -0.00066339604867001367};
  // Every operation unconditional, every choice a select: the octant is as
  // good as random from one triangle to the next (a branch on it would be
  // mispredicted half the time), and a loop over this vectorizes.
  const double ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const double high = steep ? ay : ax, low = steep ? ax : ay;
  const double t = low / (high > 0 ? high : 1.0);  // 0 / 1 at the origin
  const double s = t * t, s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
  const double p = (a[0] + a[1] * s) + (a[2] + a[3] * s) * s2 +
                   ((a[4] + a[5] * s) + (a[6] + a[7] * s) * s2) * s4 +
                   ((a[8] + a[9] * s) + (a[10] + a[11] * s) * s2) * s8;
  const double atan_t = t * p, complement = M_PI / 2 - atan_t;
  const double first = steep ? complement : atan_t;
  const double half = std::copysign(first, x) + (std::copysign(1.0, x) < 0 ? M_PI : 0.0);
  return std::copysign(half, y);
}

/// The same in float to within kFastAtan2FloatError, for float SIMD lanes (the
/// winding number's coarse pass): degree 7 in t^2 at 8 Chebyshev nodes (6e-8).
inline float fast_atan2(float y, float x) {
  static constexpr float a[8] = {0.999999882f,  -0.333318127f,  0.199669618f,  -0.140032902f,
                                 0.0986886546f, -0.0588297531f, 0.0237805186f, -0.00455979199f};
  const float ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const float high = steep ? ay : ax, low = steep ? ax : ay;
  const float t = low / (high > 0 ? high : 1.0f);
  const float s = t * t, s2 = s * s, s4 = s2 * s2;
  const float p = (a[0] + a[1] * s) + (a[2] + a[3] * s) * s2 +
                  ((a[4] + a[5] * s) + (a[6] + a[7] * s) * s2) * s4;
  const float atan_t = t * p, complement = float(M_PI / 2) - atan_t;
  const float first = steep ? complement : atan_t;
  const float half = std::copysign(first, x) + (std::copysign(1.0f, x) < 0 ? float(M_PI) : 0.0f);
  return std::copysign(half, y);
}

}  // namespace unfold
