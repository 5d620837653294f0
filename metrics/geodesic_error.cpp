#include "metrics/geodesic_error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "core/errors.h"
#include "metrics/graph_geodesics.h"

namespace unfold {
namespace {

// E_geo from the sums of D'^2, G^2 and D'G over the rows used:
// |a/|a| - b/|b||^2 = 2 - 2 <a, b> / (|a| |b|).
double value_from_sums(const Eigen::Vector3d& sums) {
  const double cosine = sums[2] / std::sqrt(sums[0] * sums[1]);
  return std::sqrt(std::max(0.0, 2 - 2 * cosine));
}

}  // namespace

GeodesicError geodesic_error(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q, const GeodesicErrorOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || Q.rows() != n || n < 2)
    throw UsageError("geodesic_error: need P and Q with one row per graph vertex, n >= 2");
  if (options.exact_limit < 0 || options.sources < 1)
    throw UsageError("geodesic_error: need exact_limit >= 0 and sources >= 1");
  GeodesicError result;
  result.exact = n <= options.exact_limit;
  std::vector<int> sources(static_cast<size_t>(n));
  std::iota(sources.begin(), sources.end(), 0);
  if (!result.exact) {
    // Partial Fisher-Yates: the first k entries become a uniform k-subset.
    const int k = std::min(options.sources, n);
    std::mt19937_64 rng(options.seed);
    for (int s = 0; s < k; ++s) {
      std::uniform_int_distribution<int> pick(s, n - 1);
      std::swap(sources[size_t(s)], sources[size_t(pick(rng))]);
    }
    sources.resize(size_t(k));
  }
  result.sources_used = int(sources.size());

  // Per-row sums of D'^2, G^2 and D'G, added in row order afterwards.
  std::vector<Eigen::Vector3d> row(sources.size());
  const NeighborLengths lengths = neighbor_lengths(graph, P);
  bool disconnected = false;
#pragma omp parallel for schedule(dynamic, 1) reduction(|| : disconnected)
  for (int s = 0; s < int(sources.size()); ++s) {
    const int i = sources[size_t(s)];
    std::vector<double> g;
    graph_geodesics(graph, lengths, i, &g);
    Eigen::Vector3d sums = Eigen::Vector3d::Zero();
    for (int j = 0; j < n; ++j) {
      if (std::isinf(g[size_t(j)])) disconnected = true;
      const double d = (Q.row(i) - Q.row(j)).norm();
      sums += Eigen::Vector3d(d * d, g[size_t(j)] * g[size_t(j)], d * g[size_t(j)]);
    }
    row[size_t(s)] = sums;
  }
  if (disconnected) throw InputError("geodesic_error: the graph is not connected");
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& sums : row) total += sums;
  if (total[0] == 0 || total[1] == 0)
    throw InputError("geodesic_error: all points coincide, distances cannot be normalised");
  result.value = value_from_sums(total);
  if (!result.exact && row.size() > 1) {
    // Delete-one jackknife over the landmark rows: the estimator is a smooth
    // function of three row means, so this is its usual standard error.
    const double k = double(row.size());
    std::vector<double> loo(row.size());
    double mean = 0;
    for (size_t s = 0; s < row.size(); ++s) mean += loo[s] = value_from_sums(total - row[s]);
    mean /= k;
    double squares = 0;
    for (double v : loo) squares += (v - mean) * (v - mean);
    result.standard_error = std::sqrt((k - 1) / k * squares);
  }
  return result;
}

}  // namespace unfold
