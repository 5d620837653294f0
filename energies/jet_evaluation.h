// Evaluates a Ceres residual functor on one or two 3-vectors with forward-mode
// automatic differentiation (ceres::Jet), returning |r|^2 and its gradient.
// This lets energy terms be written once, as Ceres functors, and be summed
// over a mesh without building a ceres::Problem.
#pragma once

#include <ceres/jet.h>

namespace unfold {

/// |f(a)|^2 for a functor with one 3-vector block and 3 residuals; adds
/// scale * d|f|^2/da into grad_a when it is not null.
template <typename Functor>
double squared_norm_1(const Functor& f, const double* a, double scale, double* grad_a) {
  if (!grad_a) {
    double r[3];
    f(a, r);
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  }
  using Jet = ceres::Jet<double, 3>;
  Jet x[3], r[3];
  for (int k = 0; k < 3; ++k) x[k] = Jet(a[k], k);
  f(x, r);
  double value = 0;
  for (int k = 0; k < 3; ++k) {
    value += r[k].a * r[k].a;
    for (int d = 0; d < 3; ++d) grad_a[d] += scale * 2 * r[k].a * r[k].v[d];
  }
  return value;
}

/// |f(a, b)|^2 for a functor with two 3-vector blocks and 3 residuals; adds
/// scale * gradients into grad_a and grad_b when they are not null.
template <typename Functor>
double squared_norm_2(const Functor& f, const double* a, const double* b, double scale,
                      double* grad_a, double* grad_b) {
  if (!grad_a) {
    double r[3];
    f(a, b, r);
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  }
  using Jet = ceres::Jet<double, 6>;
  Jet x[3], y[3], r[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = Jet(a[k], k);
    y[k] = Jet(b[k], 3 + k);
  }
  f(x, y, r);
  double value = 0;
  for (int k = 0; k < 3; ++k) {
    value += r[k].a * r[k].a;
    for (int d = 0; d < 3; ++d) {
      grad_a[d] += scale * 2 * r[k].a * r[k].v[d];
      grad_b[d] += scale * 2 * r[k].a * r[k].v[3 + d];
    }
  }
  return value;
}

}  // namespace unfold
