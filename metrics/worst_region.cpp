#include "metrics/worst_region.h"

#include <string>

#include "core/errors.h"

namespace unfold {

WorstRegion worst_region(const SurfaceDamage& damage, const Eigen::MatrixXi& F) {
  const Eigen::VectorXd& d = damage.per_vertex;
  const Eigen::Index n = d.size();
  if (n == 0 || damage.per_vertex_ratio.size() != n)
    throw UsageError("worst_region: the damage has no per-vertex values");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= n))
    throw UsageError("worst_region: a face indexes a vertex outside [0, " + std::to_string(n) +
                     ")");
  // Each face edge adds each end's damage to the other's sum; an edge shared
  // by two faces counts twice, as it does at both its ends, so the order of
  // sums between vertices barely depends on it.
  Eigen::VectorXd neighbours = Eigen::VectorXd::Zero(n);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (Eigen::Index k = 0; k < F.cols(); ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % F.cols());
      neighbours[i] += d[j];
      neighbours[j] += d[i];
    }
  Eigen::Index best = 0;
  for (Eigen::Index v = 1; v < n; ++v)
    if (d[v] > d[best] || (d[v] == d[best] && neighbours[v] > neighbours[best])) best = v;
  return {int(best), d[best], damage.per_vertex_ratio[best]};
}

double region_radius(const Eigen::MatrixX3d& V, double fraction) {
  if (!(fraction > 0 && fraction <= 1))
    throw UsageError("region radius: the fraction must be in (0, 1], not " +
                     std::to_string(fraction));
  if (V.rows() == 0) throw UsageError("region radius: no vertices");
  return fraction * (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
}

}  // namespace unfold
