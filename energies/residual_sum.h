// The one evaluator of every energy term: sums weighted squared residuals of
// small functors (Ceres style: a templated operator() on K blocks of 3
// numbers) over vertex blocks of Q,
//   e(Q) = sum_b w_b |f_b(q_b0, ..., q_b(K-1))|^2,
// with forward-mode automatic differentiation (ceres::Jet) for
//  - the value and the gradient (every term, EnergyTerm::evaluate), or
//  - the Gauss-Newton matrix J^T W J, which for residuals affine in Q is the
//    exact quadratic form of a QuadraticTerm (the local-global solver's H).
// A term lists its residual blocks once (EnergyTerm::add_residuals); no
// ceres::Problem is built.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <utility>
#include <vector>

#include "geometry/row_major.h"

namespace unfold {

class ResidualSum {
 public:
  /// Values (what add returns); with grad (n x 3) also the gradient: finish()
  /// adds scale * de/dQ into *grad.
  ResidualSum(const Eigen::MatrixX3d& Q, double scale, Eigen::MatrixX3d* grad)
      : q_(Q), scale_(scale), grad_(grad) {
    if (grad_) g_.setZero(Q.rows(), 3);
  }

  /// The n x n matrix H of the residuals' Gauss-Newton form at Q: J^T W J with
  /// the Jacobian J of every block acting alike on x, y and z (its 3 x 3 parts
  /// are multiples of I), so that e(Q) = tr(Q^T H Q) + (linear) + (constant)
  /// for affine residuals. finish() adds scale * H into *hessian as triplets.
  /// add() throws UsageError for a block whose Jacobian is not of that form.
  ResidualSum(const Eigen::MatrixX3d& Q, double scale, std::vector<Eigen::Triplet<double>>* hessian)
      : q_(Q), scale_(scale), hessian_(hessian) {}

  /// The block weight * |f(q_v0, ..., q_v(K-1))|^2 of R residuals on K vertices
  /// (unscaled; the caller sums them: a running sum kept here would be stored
  /// to memory at every block, as it might alias the positions).
  /// @param weight any sign (the stretch term subtracts)
  template <int R, int K, typename Functor>
  double add(const Functor& f, const std::array<int, K>& vertices, double weight = 1.0) {
    // The value alone is the hot path (energy sweeps): kept small, so that it inlines.
    if (!grad_ && !hessian_) return weight * squared_norm<R, K>(f, vertices);
    return weight * differentiate<R, K>(f, vertices, weight);
  }

  /// Adds the accumulated gradient into grad. Call once, after the last add.
  void finish() {
    if (grad_) *grad_ += g_;
  }

 private:
  template <int R, int K, typename Functor>
  double squared_norm(const Functor& f, const std::array<int, K>& vertices) const;
  /// |f|^2, with its gradient or Gauss-Newton matrix accumulated (times weight).
  template <int R, int K, typename Functor>
  double differentiate(const Functor& f, const std::array<int, K>& vertices, double weight);
  template <int R, int K>
  void add_gauss_newton(const ceres::Jet<double, 3 * K> (&r)[R], const std::array<int, K>& vertices,
                        double weight);
  [[noreturn]] static void throw_anisotropic();

  RowMatrixX3d q_, g_;
  double scale_;
  Eigen::MatrixX3d* grad_ = nullptr;
  std::vector<Eigen::Triplet<double>>* hessian_ = nullptr;
};

namespace internal {
template <typename Functor, typename T, size_t... I>
void call_functor(const Functor& f, const std::array<const T*, sizeof...(I)>& x, T* r,
                  std::index_sequence<I...>) {
  f(x[I]..., r);
}
}  // namespace internal

template <int R, int K, typename Functor>
double ResidualSum::squared_norm(const Functor& f, const std::array<int, K>& vertices) const {
  std::array<const double*, K> x;
  for (size_t b = 0; b < size_t(K); ++b) x[b] = q_.row(vertices[b]).data();
  double r[R], value = 0;
  internal::call_functor(f, x, r, std::make_index_sequence<K>());
  for (int k = 0; k < R; ++k) value += r[k] * r[k];
  return value;
}

template <int R, int K, typename Functor>
double ResidualSum::differentiate(const Functor& f, const std::array<int, K>& vertices,
                                  double weight) {
  using Jet = ceres::Jet<double, 3 * K>;
  Jet storage[K][3], r[R];
  std::array<const Jet*, K> x;
  for (int b = 0; b < K; ++b) {
    for (int d = 0; d < 3; ++d) storage[b][d] = Jet(q_(vertices[size_t(b)], d), 3 * b + d);
    x[size_t(b)] = storage[b];
  }
  internal::call_functor(f, x, r, std::make_index_sequence<K>());
  double value = 0;
  for (int k = 0; k < R; ++k) value += r[k].a * r[k].a;
  if (grad_) {
    const double s = 2 * scale_ * weight;
    for (int k = 0; k < R; ++k)
      for (int b = 0; b < K; ++b)
        for (int d = 0; d < 3; ++d) g_(vertices[size_t(b)], d) += s * r[k].a * r[k].v[3 * b + d];
  }
  if (hessian_) add_gauss_newton<R, K>(r, vertices, weight);
  return value;
}

template <int R, int K>
void ResidualSum::add_gauss_newton(const ceres::Jet<double, 3 * K> (&r)[R],
                                   const std::array<int, K>& vertices, double weight) {
  Eigen::Matrix<double, 3 * K, 3 * K> JtJ = Eigen::Matrix<double, 3 * K, 3 * K>::Zero();
  for (int k = 0; k < R; ++k) JtJ.noalias() += r[k].v * r[k].v.transpose();
  const double tolerance = 1e-12 * JtJ.cwiseAbs().maxCoeff();
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < K; ++b) {
      const Eigen::Matrix3d block = JtJ.template block<3, 3>(3 * a, 3 * b);
      const double c = block(0, 0);
      if (!((block - c * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tolerance))
        throw_anisotropic();
      if (c != 0)
        hessian_->emplace_back(vertices[size_t(a)], vertices[size_t(b)], scale_ * weight * c);
    }
}

}  // namespace unfold
