// atan2 without the libm call: the winding number's near field takes one per
// triangle, and libm's was a third of the robust route's carve.
#pragma once

#include <cmath>

namespace unfold {

/// The bound on |fast_atan2(y, x) - atan2(y, x)| that tests/fast_atan2_test.cpp checks.
constexpr double kFastAtan2Error = 1e-10;
/// The same for the float overload (its polynomial's 6e-8 and float's rounding).
constexpr double kFastAtan2FloatError = 5e-7;

namespace fast_atan2_detail {

// atan2 from atan on [0, 1]: the octant reduction t = min(|x|, |y|) / max(|x|,
// |y|), atan(t) = t p(t^2) by the caller's p, then the octant put back. Every
// operation unconditional, every choice a select: the octant is as good as
// random from one triangle to the next (a branch on it would be mispredicted
// half the time), and a loop over this vectorizes.
template <typename Real, typename Polynomial>
inline Real atan2_by_octant(Real y, Real x, const Polynomial& p) {
  const Real ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const Real high = steep ? ay : ax, low = steep ? ax : ay;
  const Real t = low / (high > 0 ? high : Real(1));  // 0 / 1 at the origin
  const Real atan_t = t * p(t * t), complement = Real(M_PI / 2) - atan_t;
  const Real first = steep ? complement : atan_t;
  const Real half =
      std::copysign(first, x) + (std::copysign(Real(1), x) < 0 ? Real(M_PI) : Real(0));
  return std::copysign(half, y);
}

}  // namespace fast_atan2_detail

/// atan2(y, x) to within kFastAtan2Error, for finite y and x; (+-0, +-0) gives
/// +-0 or +-pi as std::atan2 does. The octant reduction t = min(|x|, |y|) /
/// max(|x|, |y|) in [0, 1], then atan(t) = t p(t^2) with p of degree 11
/// interpolating atan(sqrt s) / sqrt s at 12 Chebyshev nodes on [0, 1] (error
/// 4e-11), evaluated in Estrin's scheme: a few independent multiply-adds deep,
/// where a Horner chain was no faster than libm.
inline double fast_atan2(double y, double x) {
  return fast_atan2_detail::atan2_by_octant(y, x, [](double s) {
    static constexpr double a[12] = {
        0.99999999992930244,   -0.33333331290885149,  0.19999901102156251,
        -0.14283813257109715,  0.11091922983234306,   -0.089741720766549321,
        0.072282787413693456,  -0.053956688586216231, 0.033826229014569734,
        -0.015828330421451632, 0.0047324874515955644, -0.00066339604867001367};
    const double s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
    return (a[0] + a[1] * s) + (a[2] + a[3] * s) * s2 +
           ((a[4] + a[5] * s) + (a[6] + a[7] * s) * s2) * s4 +
           ((a[8] + a[9] * s) + (a[10] + a[11] * s) * s2) * s8;
  });
}

/// The same in float to within kFastAtan2FloatError, for float SIMD lanes (the
/// winding number's coarse pass): p of degree 7 at 8 Chebyshev nodes (6e-8).
inline float fast_atan2(float y, float x) {
  return fast_atan2_detail::atan2_by_octant(y, x, [](float s) {
    static constexpr float a[8] = {0.999999882f,  -0.333318127f,  0.199669618f,  -0.140032902f,
                                   0.0986886546f, -0.0588297531f, 0.0237805186f, -0.00455979199f};
    const float s2 = s * s, s4 = s2 * s2;
    return (a[0] + a[1] * s) + (a[2] + a[3] * s) * s2 +
           ((a[4] + a[5] * s) + (a[6] + a[7] * s) * s2) * s4;
  });
}

}  // namespace unfold
