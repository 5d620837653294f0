// Evaluates a Ceres residual functor on K blocks of 3 doubles with
// forward-mode automatic differentiation (ceres::Jet), returning |r|^2 and its
// gradient. Energy terms are written once, as Ceres functors, and summed over a
// mesh without building a ceres::Problem.
#pragma once

#include <ceres/jet.h>

#include <array>
#include <utility>

namespace unfold {

namespace internal {
template <typename Functor, typename T, size_t... I>
void call_functor(const Functor& f, const std::array<const T*, sizeof...(I)>& x, T* r,
                  std::index_sequence<I...>) {
  f(x[I]..., r);
}
}  // namespace internal

/// |f(x_0, ..., x_{K-1})|^2 for a functor with K 3-vector blocks and R residuals.
/// When grad is not null, adds scale * d|f|^2/dx_k into grad[k] (3 doubles each).
template <int R, int K, typename Functor>
double squared_norm(const Functor& f, const std::array<const double*, K>& x, double scale,
                    const std::array<double*, K>* grad) {
  double value = 0;
  if (!grad) {
    double r[R];
    internal::call_functor(f, x, r, std::make_index_sequence<K>());
    for (int k = 0; k < R; ++k) value += r[k] * r[k];
    return value;
  }
  using Jet = ceres::Jet<double, 3 * K>;
  Jet storage[K][3], r[R];
  std::array<const Jet*, K> jx;
  for (int b = 0; b < K; ++b) {
    for (int d = 0; d < 3; ++d) storage[b][d] = Jet(x[size_t(b)][d], 3 * b + d);
    jx[size_t(b)] = storage[b];
  }
  internal::call_functor(f, jx, r, std::make_index_sequence<K>());
  for (int k = 0; k < R; ++k) {
    value += r[k].a * r[k].a;
    for (int b = 0; b < K; ++b)
      for (int d = 0; d < 3; ++d) (*grad)[size_t(b)][d] += scale * 2 * r[k].a * r[k].v[3 * b + d];
  }
  return value;
}

}  // namespace unfold
