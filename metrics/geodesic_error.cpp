#include "metrics/geodesic_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "core/errors.h"
#include "core/progress.h"
#include "metrics/graph_geodesics.h"

namespace unfold {
namespace {

// E_geo from the sums of D'^2, G^2 and D'G over the rows used:
// |a/|a| - b/|b||^2 = 2 - 2 <a, b> / (|a| |b|).
double value_from_sums(const Eigen::Vector3d& sums) {
  const double cosine = sums[2] / std::sqrt(sums[0] * sums[1]);
  return std::sqrt(std::max(0.0, 2 - 2 * cosine));
}

// The sources of the rows used: every vertex when n <= exact_limit, else a
// uniform random subset of `sources` vertices drawn with the fixed seed.
std::vector<int> landmark_sources(int n, const GeodesicErrorOptions& options, bool* exact) {
  if (options.exact_limit < 0 || options.sources < 1)
    throw UsageError("geodesic_error: need exact_limit >= 0 and sources >= 1");
  *exact = n <= options.exact_limit;
  std::vector<int> sources(static_cast<size_t>(n));
  std::iota(sources.begin(), sources.end(), 0);
  if (!*exact) {
    // Partial Fisher-Yates: the first k entries become a uniform k-subset.
    const int k = std::min(options.sources, n);
    std::mt19937_64 rng(options.seed);
    for (int s = 0; s < k; ++s) {
      std::uniform_int_distribution<int> pick(s, n - 1);
      std::swap(sources[size_t(s)], sources[size_t(pick(rng))]);
    }
    sources.resize(size_t(k));
  }
  return sources;
}

// Sums of D'^2, G^2 and D'G over one row (source i, distances g).
Eigen::Vector3d row_sums(const Eigen::MatrixX3d& Q, int i, const double* g) {
  Eigen::Vector3d sums = Eigen::Vector3d::Zero();
  for (int j = 0; j < int(Q.rows()); ++j) {
    const double d = (Q.row(i) - Q.row(j)).norm();
    sums += Eigen::Vector3d(d * d, g[j] * g[j], d * g[j]);
  }
  return sums;
}

// The graph distances from every source, in parallel, each row handed to
// visit(s, distances) on the thread that computed it.
// @throws InputError if some vertex is unreachable
template <typename Visit>
void for_each_row(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                  const std::vector<int>& sources, const Visit& visit) {
  const NeighborLengths lengths = neighbor_lengths(graph, P);
  bool disconnected = false;
#pragma omp parallel for schedule(dynamic, 1) reduction(|| : disconnected)
  for (int s = 0; s < int(sources.size()); ++s) {
    std::vector<double> g;
    graph_geodesics(graph, lengths, sources[size_t(s)], &g);
    if (std::any_of(g.begin(), g.end(), [](double x) { return std::isinf(x); }))
      disconnected = true;
    visit(s, g);
  }
  if (disconnected) throw InputError("geodesic_error: the graph is not connected");
}

// E_geo and its jackknife standard error from the per-row sums, added in row order.
GeodesicError finish(const std::vector<Eigen::Vector3d>& row, bool exact) {
  GeodesicError result;
  result.exact = exact;
  result.sources_used = int(row.size());
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& sums : row) total += sums;
  if (total[0] == 0 || total[1] == 0)
    throw InputError("geodesic_error: all points coincide, distances cannot be normalised");
  result.value = value_from_sums(total);
  if (!exact && row.size() > 1) {
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

}  // namespace

GeodesicError geodesic_error(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q, const GeodesicErrorOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || Q.rows() != n || n < 2)
    throw UsageError("geodesic_error: need P and Q with one row per graph vertex, n >= 2");
  report_stage("E_geo of " + std::to_string(n) + " vertices");
  bool exact = false;
  const std::vector<int> sources = landmark_sources(n, options, &exact);
  // Each row's sums as soon as its distances are known: no n x sources matrix.
  std::vector<Eigen::Vector3d> row(sources.size());
  for_each_row(graph, P, sources, [&](int s, const std::vector<double>& g) {
    row[size_t(s)] = row_sums(Q, sources[size_t(s)], g.data());
  });
  return finish(row, exact);
}

GeodesicRows geodesic_error_precomputation(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                           const GeodesicErrorOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || n < 2)
    throw UsageError("geodesic_error: need P with one row per graph vertex, n >= 2");
  GeodesicRows rows;
  rows.sources = landmark_sources(n, options, &rows.exact);
  rows.G.resize(Eigen::Index(rows.sources.size()), n);
  for_each_row(graph, P, rows.sources, [&](int s, const std::vector<double>& g) {
    rows.G.row(s) = Eigen::Map<const Eigen::RowVectorXd>(g.data(), n);
  });
  return rows;
}

GeodesicError geodesic_error_solve(const GeodesicRows& rows, const Eigen::MatrixX3d& Q) {
  if (Q.rows() != rows.G.cols() || rows.sources.empty())
    throw UsageError("geodesic_error_solve: need Q with one row per column of G");
  std::vector<Eigen::Vector3d> row(rows.sources.size());
#pragma omp parallel for schedule(static)
  for (int s = 0; s < int(rows.sources.size()); ++s)
    row[size_t(s)] = row_sums(Q, rows.sources[size_t(s)], rows.G.row(s).data());
  return finish(row, rows.exact);
}

namespace {

// The faces' edge graph, or an empty one when its edges do not join every vertex.
EdgeGraph connected_surface_graph(const Eigen::MatrixX3d& V, const Eigen::MatrixXi& F) {
  EdgeGraph graph = build_edge_graph(int(V.rows()), F);
  if (V.rows() < 2 || connected_components(graph) != 1) return EdgeGraph{};
  return graph;
}

// E_geo over a surface whose faces' edges fall apart: NaN.
GeodesicError no_surface_error() {
  GeodesicError none;
  none.value = std::numeric_limits<double>::quiet_NaN();
  return none;
}

}  // namespace

GeodesicError surface_geodesic_error(const Eigen::MatrixX3d& V, const Eigen::MatrixXi& F,
                                     const Eigen::MatrixX3d& Q,
                                     const GeodesicErrorOptions& options) {
  if (Q.rows() != V.rows())
    throw UsageError("surface_geodesic_error: need V and Q with one row per surface vertex");
  const EdgeGraph graph = connected_surface_graph(V, F);
  if (graph.num_vertices == 0) return no_surface_error();
  return geodesic_error(graph, V, Q, options);
}

GeodesicRows surface_geodesic_error_precomputation(const Eigen::MatrixX3d& V,
                                                   const Eigen::MatrixXi& F,
                                                   const GeodesicErrorOptions& options) {
  const EdgeGraph graph = connected_surface_graph(V, F);
  if (graph.num_vertices == 0) return GeodesicRows{};
  return geodesic_error_precomputation(graph, V, options);
}

GeodesicError surface_geodesic_error_solve(const GeodesicRows& rows, const Eigen::MatrixX3d& Q) {
  if (rows.sources.empty()) return no_surface_error();
  return geodesic_error_solve(rows, Q);
}

}  // namespace unfold
