#include "solvers/anderson_acceleration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/parallel_segments.h"

namespace unfold {

void AndersonAcceleration::next(const Eigen::Ref<const Eigen::VectorXd>& x,
                                const Eigen::Ref<const Eigen::VectorXd>& g,
                                Eigen::Ref<Eigen::VectorXd> out) {
  const Eigen::Index n = x.size();
  const bool differences = has_last_ && last_f_.size() == n;
  if (differences) {
    newest_ = (newest_ + 1) % window_;
    count_ = std::min(count_ + 1, window_);
  } else {
    dF_.resize(n, window_);
    dG_.resize(n, window_);
    gram_.resize(window_, window_);
    last_g_.resize(n);
    count_ = 0;
    newest_ = -1;
  }
  f_.resize(n);
  // The residual, the newest differences and the image kept for the next
  // step, in one sweep over the vectors.
  for_segments(n, [&](Eigen::Index begin, Eigen::Index size) {
    f_.segment(begin, size) = g.segment(begin, size) - x.segment(begin, size);
    if (differences) {
      dF_.col(newest_).segment(begin, size) =
          f_.segment(begin, size) - last_f_.segment(begin, size);
      dG_.col(newest_).segment(begin, size) = g.segment(begin, size) - last_g_.segment(begin, size);
    }
    last_g_.segment(begin, size) = g.segment(begin, size);
  });
  has_last_ = true;
  // The Gram matrix's new row and dF^T f: each dot product whole on one
  // thread (in Eigen's order), the two sets side by side.
  Eigen::VectorXd dF_f(count_);
#pragma omp parallel sections num_threads(2) if (n >= kMinParallelEntries)
  {
#pragma omp section
    if (differences)
      for (int s = 0; s < count_; ++s)
        gram_(newest_, s) = gram_(s, newest_) = dF_.col(newest_).dot(dF_.col(s));
#pragma omp section
    if (count_ > 0) dF_f.noalias() = dF_.leftCols(count_).transpose() * f_;
  }
  Eigen::VectorXd gamma = Eigen::VectorXd::Zero(count_);
  if (count_ > 0) {
    // Scaled to a unit diagonal, the Gram matrix's eigenvalues say which
    // combinations of differences are resolved; a zero difference (a repeated
    // step) has no scale and stays out.
    Eigen::VectorXd scale(count_);
    for (int s = 0; s < count_; ++s) scale(s) = gram_(s, s) > 0 ? 1 / std::sqrt(gram_(s, s)) : 0.0;
    const Eigen::MatrixXd C =
        scale.asDiagonal() * gram_.topLeftCorner(count_, count_) * scale.asDiagonal();
    const Eigen::VectorXd r = scale.asDiagonal() * dF_f;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(C);
    const Eigen::VectorXd& lambda = eigen.eigenvalues();
    const double cutoff = 1e-12 * std::max(lambda.maxCoeff(), 0.0);
    Eigen::VectorXd y = eigen.eigenvectors().transpose() * r;
    for (int s = 0; s < count_; ++s) y(s) = lambda(s) > cutoff ? y(s) / lambda(s) : 0.0;
    gamma = scale.asDiagonal() * (eigen.eigenvectors() * y);
  }
  last_f_.swap(f_);
  // What Eigen makes of out = g - dG gamma: g, then the product subtracted in
  // place; each entry's sum over the window is the same in any segment.
  for_segments(n, [&](Eigen::Index begin, Eigen::Index size) {
    auto segment = out.segment(begin, size);
    segment = g.segment(begin, size);
    if (count_ > 0) segment.noalias() -= dG_.middleRows(begin, size).leftCols(count_) * gamma;
  });
}

void AndersonAcceleration::reset() {
  has_last_ = false;
  count_ = 0;
  newest_ = -1;
}

}  // namespace unfold
