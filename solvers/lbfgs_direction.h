// L-BFGS directions (Nocedal 1980, the two-loop recursion) with a given
// initial inverse Hessian. With the inverse of local-global ARAP's global
// matrix as that, it is the quasi-Newton method of Liu, Bouaziz and Kavan
// 2017 ("Quasi-Newton methods for real-time simulation of hyperelastic
// materials"): a step costs one solve, as a local-global step does, and the
// last few steps' gradient changes supply the curvature the global matrix
// leaves out (how the best rotations turn as the points move), which makes
// local-global steps crawl along soft modes (docs/performance.md, the
// anchored steps' convergence).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace unfold {

class LbfgsDirection {
 public:
  /// r = H0 q: the initial inverse Hessian applied to q (symmetric positive definite).
  using InitialInverse = std::function<void(const Eigen::MatrixX3d& q, Eigen::MatrixX3d* r)>;

  /// @param window how many past steps are kept (>= 1)
  explicit LbfgsDirection(int window);

  /// The quasi-Newton direction d = -H g at gradient g, H the inverse Hessian
  /// estimate: H0 updated by the kept pairs, newest last; with none, -H0 g.
  /// Each loop of the recursion sweeps the vectors once per pair, on all
  /// threads from kMinParallelRows rows (core/parallel_segments.h: the same
  /// direction on any thread count).
  void direction(const Eigen::MatrixX3d& g, const InitialInverse& h0, Eigen::MatrixX3d* d);

  /// Keeps the step s = x' - x and the gradient change y = g' - g (the
  /// gradients at its ends) if s.y > 0, the curvature condition that keeps H
  /// positive definite; the oldest pair is dropped once the window is full.
  /// Returns whether it was kept.
  bool update(const Eigen::MatrixX3d& s, const Eigen::MatrixX3d& g_after,
              const Eigen::MatrixX3d& g_before);

  /// Scales the initial inverse Hessian of the directions that use kept pairs:
  /// gamma H0 instead of H0 (Nocedal and Wright's gamma = s.y / y.y, with H0's
  /// own curvature: gamma = s.H0^-1 s / s.y makes the scaled H0 as stiff along
  /// the newest step as the function was). A direction without pairs stays -H0 g.
  /// @pre gamma > 0 and finite (unchecked)
  void scale_initial_inverse(double gamma) { scale_ = gamma; }

  /// Forgets every pair and the scale (the next direction is -H0 g).
  void reset() {
    count_ = 0;
    scale_ = 1;
  }

  /// Pairs held.
  int size() const { return count_; }

  /// s.y of the newest pair kept (> 0).
  /// @pre size() > 0 (unchecked)
  double newest_curvature() const { return 1 / rho_[size_t(newest_)]; }

 private:
  int window_;
  int count_ = 0;     // pairs held: ring slots [0, count_)
  int newest_ = -1;   // the slot of the newest pair
  double scale_ = 1;  // of H0, with pairs
  std::vector<Eigen::MatrixX3d> s_, y_;
  std::vector<double> rho_, alpha_;  // 1 / s.y per slot; the first loop's coefficients
  Eigen::MatrixX3d q_;
};

}  // namespace unfold
