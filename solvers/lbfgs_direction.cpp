#include "solvers/lbfgs_direction.h"

#include <algorithm>

#include "core/errors.h"
#include "core/parallel_segments.h"

namespace unfold {
namespace {

Eigen::Map<Eigen::VectorXd> flat(Eigen::MatrixX3d& a) { return {a.data(), a.size()}; }
Eigen::Map<const Eigen::VectorXd> flat(const Eigen::MatrixX3d& a) { return {a.data(), a.size()}; }

}  // namespace

LbfgsDirection::LbfgsDirection(int window)
    : window_(window),
      s_(size_t(std::max(window, 0))),
      y_(s_.size()),
      rho_(s_.size()),
      alpha_(s_.size()) {
  if (window < 1) throw UsageError("LbfgsDirection: window must be >= 1");
}

void LbfgsDirection::direction(const Eigen::MatrixX3d& g, const InitialInverse& h0,
                               Eigen::MatrixX3d* d) {
  const Eigen::Index n = g.size();
  const auto slot = [&](int c) { return size_t((newest_ - c + window_) % window_); };
  // Newest to oldest: q = g minus alpha_k y_k, alpha_k = rho_k s_k.q. Each sweep
  // also takes the next pair's dot product with the q it leaves.
  q_.resize(g.rows(), 3);
  auto q = flat(q_);
  const auto g_flat = flat(g);
  double next = sum_segments(n, [&](Eigen::Index b, Eigen::Index size) {
    q.segment(b, size) = g_flat.segment(b, size);
    return count_ > 0 ? flat(s_[slot(0)]).segment(b, size).dot(q.segment(b, size)) : 0.0;
  });
  for (int c = 0; c < count_; ++c) {
    const size_t k = slot(c);
    alpha_[k] = rho_[k] * next;
    const auto y = flat(y_[k]);
    next = sum_segments(n, [&](Eigen::Index b, Eigen::Index size) {
      q.segment(b, size) -= alpha_[k] * y.segment(b, size);
      return c + 1 < count_ ? flat(s_[slot(c + 1)]).segment(b, size).dot(q.segment(b, size)) : 0.0;
    });
  }
  h0(q_, d);
  if (count_ > 0 && scale_ != 1) *d *= scale_;
  // Oldest to newest: d += (alpha_k - rho_k y_k.d) s_k, each sweep taking the
  // next pair's y.d; the last one also turns d into -H g.
  auto r = flat(*d);
  next = count_ > 0 ? flat(y_[slot(count_ - 1)]).dot(r) : 0.0;
  for (int c = count_ - 1; c >= 0; --c) {
    const size_t k = slot(c);
    const double coefficient = alpha_[k] - rho_[k] * next;
    const auto s = flat(s_[k]);
    next = sum_segments(n, [&](Eigen::Index b, Eigen::Index size) {
      auto segment = r.segment(b, size);
      segment += coefficient * s.segment(b, size);
      if (c > 0) return flat(y_[slot(c - 1)]).segment(b, size).dot(segment);
      segment = -segment;
      return 0.0;
    });
  }
  if (count_ == 0) r = -r;
}

bool LbfgsDirection::update(const Eigen::MatrixX3d& s, const Eigen::MatrixX3d& g_after,
                            const Eigen::MatrixX3d& g_before) {
  const Eigen::Index n = s.size();
  const auto s_flat = flat(s), after = flat(g_after), before = flat(g_before);
  const double sy = sum_segments(n, [&](Eigen::Index b, Eigen::Index size) {
    return s_flat.segment(b, size).dot(after.segment(b, size) - before.segment(b, size));
  });
  if (!(sy > 0)) return false;
  newest_ = (newest_ + 1) % window_;
  const size_t k = size_t(newest_);
  s_[k].resize(s.rows(), 3);
  y_[k].resize(s.rows(), 3);
  auto s_slot = flat(s_[k]), y_slot = flat(y_[k]);
  for_segments(n, [&](Eigen::Index b, Eigen::Index size) {
    s_slot.segment(b, size) = s_flat.segment(b, size);
    y_slot.segment(b, size) = after.segment(b, size) - before.segment(b, size);
  });
  rho_[k] = 1 / sy;
  count_ = std::min(count_ + 1, window_);
  return true;
}

}  // namespace unfold
