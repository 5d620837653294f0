#include "energies/soft_joint_factors.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "mesh/best_rotations.h"

namespace unfold {

constexpr double kNoTurn = 1e-6;  // radians

std::vector<double> soft_joint_factors(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const Eigen::MatrixX3d& Q, const SoftenOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || Q.rows() != n)
    throw UsageError("soft_joint_factors: P and Q need one row per graph vertex");
  if (!(options.scale > 0) || !std::isfinite(options.scale) || !(options.floor > 0) ||
      !(options.floor <= 1))
    throw UsageError("soft_joint_factors: need scale > 0 and floor in (0, 1]");
  Rotations R;
  best_rotations(graph, P, Q, &R);
  // k per edge, each edge seen from its lower end.
  std::vector<double> turn(size_t(graph.num_edges()), 0.0);
  double largest_angle = 0;
  for (int i = 0; i < n; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      if (j < i) continue;
      const double cosine =
          std::clamp(((R[size_t(i)].transpose() * R[size_t(j)]).trace() - 1) / 2, -1.0, 1.0);
      const double angle = std::acos(cosine), length = (P.row(i) - P.row(j)).norm();
      largest_angle = std::max(largest_angle, angle);
      turn[size_t(graph.neighbor_edge[size_t(k)])] = length > 0 ? angle / length : 0;
    }
  std::vector<double> sorted = turn;
  const auto middle = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = sorted.empty() ? 0 : *middle;
  std::vector<double> factors(turn.size(), 1.0);
  // Below kNoTurn every turn is roundoff of a rigid motion: nothing to soften.
  if (!(median > 0) || largest_angle < kNoTurn) return factors;
  const double unit = options.scale * median;
  for (size_t e = 0; e < turn.size(); ++e)
    factors[e] = std::max(options.floor, 1 / (1 + std::pow(turn[e] / unit, 2)));
  return factors;
}

}  // namespace unfold
