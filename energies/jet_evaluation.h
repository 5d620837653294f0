// Evaluates a Ceres residual functor on K blocks of 3 doubles with
// forward-mode automatic differentiation (ceres::Jet), returning |r|^2 and its
// gradient. Energy terms are written once, as Ceres functors, and summed over a
// mesh without building a ceres::Problem.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <array>
#include <utility>

#include "geometry/row_major.h"

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

/// Sums squared residuals of functors over vertex blocks of Q: what every
/// term's evaluate() does. Holds the row-major copy of Q that the functors
/// read and the gradient accumulated so far.
class ResidualSum {
 public:
  /// @param scale multiplies the gradient added into *grad (not the value)
  /// @param grad  n x 3, or null for values only
  ResidualSum(const Eigen::MatrixX3d& Q, double scale, Eigen::MatrixX3d* grad)
      : q_(Q), scale_(scale), grad_(grad) {
    if (grad_) g_.setZero(Q.rows(), 3);
  }
  /// |f(q_v0, ..., q_vK-1)|^2; its gradient times scale * sign is accumulated.
  template <int R, int K, typename Functor>
  double add(const Functor& f, const std::array<int, K>& vertices, double sign = 1.0) {
    std::array<const double*, K> x;
    std::array<double*, K> g;
    for (size_t k = 0; k < size_t(K); ++k) {
      x[k] = q_.row(vertices[k]).data();
      g[k] = grad_ ? g_.row(vertices[k]).data() : nullptr;
    }
    return squared_norm<R, K>(f, x, sign * scale_, grad_ ? &g : nullptr);
  }
  /// Adds the accumulated gradient into grad; call once, after the last add.
  void finish() {
    if (grad_) *grad_ += g_;
  }

 private:
  RowMatrixX3d q_, g_;
  double scale_;
  Eigen::MatrixX3d* grad_;
};

}  // namespace unfold
