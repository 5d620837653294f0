#include "solvers/lsmds.h"

#include <glog/logging.h>

#include <cmath>
#include <limits>

#include "core/errors.h"
#include "metrics/graph_geodesics.h"

namespace unfold {

void validate_lsmds_options(const LsmdsOptions& o) {
  if (o.exact_limit < 0) throw UsageError("config key 'lsmds.exact_limit' must be >= 0");
  if (o.landmarks < 4) throw UsageError("config key 'lsmds.landmarks' must be at least 4");
  if (o.max_iterations < 1) throw UsageError("config key 'lsmds.max_iterations' must be >= 1");
  if (!(std::isfinite(o.tolerance) && o.tolerance >= 0))
    throw UsageError("config key 'lsmds.tolerance' must be a finite number >= 0");
}

LandmarkDistances lsmds_distances(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                  const LsmdsOptions& options) {
  validate_lsmds_options(options);
  const int n = graph.num_vertices;
  if (P.rows() != n) throw UsageError("lsmds: positions do not match the edge graph");
  LandmarkDistances d;
  auto check_row = [&](const std::vector<double>& row, int source) {
    for (double x : row)
      if (!std::isfinite(x))
        throw NumericalError("lsmds: the tet edge graph is disconnected (from vertex " +
                             std::to_string(source) + ")");
  };
  const NeighborLengths lengths = neighbor_lengths(graph, P);
  if (n <= options.exact_limit || n <= options.landmarks) {
    d.rows.resize(n, n);
    d.landmarks.resize(size_t(n));
#pragma omp parallel for schedule(dynamic, 16)
    for (int i = 0; i < n; ++i) {
      d.landmarks[size_t(i)] = i;
      std::vector<double> row;
      graph_geodesics(graph, lengths, i, &row);
      d.rows.row(i) = Eigen::Map<const Eigen::RowVectorXd>(row.data(), n);
    }
    if (!d.rows.allFinite()) throw NumericalError("lsmds: the tet edge graph is disconnected");
    return d;
  }
  // Farthest-point sampling: each landmark is the vertex farthest from those chosen.
  const int k = options.landmarks;
  d.rows.resize(k, n);
  Eigen::VectorXd nearest = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  int next = 0;
  for (int a = 0; a < k; ++a) {
    d.landmarks.push_back(next);
    std::vector<double> row;
    graph_geodesics(graph, lengths, next, &row);
    check_row(row, next);
    d.rows.row(a) = Eigen::Map<const Eigen::RowVectorXd>(row.data(), n);
    nearest = nearest.cwiseMin(d.rows.row(a).transpose());
    nearest.maxCoeff(&next);
  }
  return d;
}

double guttman_transform(const LandmarkDistances& distances, const Eigen::MatrixX3d& X,
                         Eigen::MatrixX3d* next) {
  const int n = int(X.rows());
  const int k = int(distances.landmarks.size());
  std::vector<int> landmark_index(size_t(n), -1);
  for (int a = 0; a < k; ++a) landmark_index[size_t(distances.landmarks[size_t(a)])] = a;
  // Y = B(X) X over the weighted pairs (each once), and the stress at X.
  Eigen::MatrixX3d Y = Eigen::MatrixX3d::Zero(n, 3);
  double stress = 0;
#pragma omp parallel if (double(k) * n > 2e5)
  {
    Eigen::MatrixX3d local = Eigen::MatrixX3d::Zero(n, 3);
#pragma omp for schedule(dynamic, 4) reduction(+ : stress)
    for (int a = 0; a < k; ++a) {
      const int i = distances.landmarks[size_t(a)];
      const Eigen::RowVector3d xi = X.row(i);
      Eigen::RowVector3d yi = Eigen::RowVector3d::Zero();
      for (int j = 0; j < n; ++j) {
        const int b = landmark_index[size_t(j)];
        if (j == i || (b >= 0 && b < a)) continue;  // landmark pairs once
        const Eigen::RowVector3d diff = xi - X.row(j);
        const double dist = diff.norm(), target = distances.rows(a, j);
        stress += (target - dist) * (target - dist);
        if (dist == 0) continue;
        const Eigen::RowVector3d c = (target / dist) * diff;
        yi += c;
        local.row(j) -= c;
      }
      local.row(i) += yi;
    }
#pragma omp critical
    Y += local;
  }
  // V X = Y with V the weights' Laplacian: landmarks are joined to all n - 1
  // others, the other m vertices to the k landmarks only, which solves in
  // closed form (docs/baselines.md); k = n gives the exact X = Y / n.
  Eigen::RowVector3d others_sum = Eigen::RowVector3d::Zero();
  for (int j = 0; j < n; ++j)
    if (landmark_index[size_t(j)] < 0) others_sum += Y.row(j);
  next->resize(n, 3);
  for (int j = 0; j < n; ++j)
    next->row(j) = landmark_index[size_t(j)] >= 0 ? (Y.row(j) + others_sum / k) / n
                                                  : Eigen::RowVector3d(Y.row(j) / k);
  next->rowwise() -= next->colwise().mean();
  return stress;
}

LsmdsResult smacof(const LandmarkDistances& distances, const Eigen::MatrixX3d& X0,
                   const LsmdsOptions& options, const LsmdsCallback& on_iterate) {
  validate_lsmds_options(options);
  const int n = int(X0.rows());
  if (distances.rows.cols() != n ||
      distances.rows.rows() != Eigen::Index(distances.landmarks.size()))
    throw UsageError("smacof: the distances do not match the initial positions");
  LsmdsResult result;
  result.exact = int(distances.landmarks.size()) == n;
  result.positions = X0.rowwise() - X0.colwise().mean();
  Eigen::MatrixX3d next;
  for (int it = 0; it < options.max_iterations; ++it) {
    const double stress = guttman_transform(distances, result.positions, &next);
    result.stress.push_back(stress);
    if (it > 0 && on_iterate) on_iterate(it, result.positions, stress);
    if (it > 0) {
      const double previous = result.stress[result.stress.size() - 2];
      if (previous - stress <= options.tolerance * previous) {
        result.converged = true;
        break;  // the transform just computed is not taken: the stress has settled
      }
    }
    result.positions = next;
    ++result.iterations;
  }
  if (!result.converged) {
    Eigen::MatrixX3d unused;
    result.stress.push_back(guttman_transform(distances, result.positions, &unused));
    if (on_iterate) on_iterate(result.iterations, result.positions, result.stress.back());
  }
  LOG(INFO) << "lsmds (" << (result.exact ? "exact" : "landmarks") << ", "
            << distances.landmarks.size() << " rows): stress " << result.stress.front() << " -> "
            << result.stress.back() << " in " << result.iterations << " iterations";
  return result;
}

LsmdsResult lsmds(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const LsmdsOptions& options,
                  const LsmdsCallback& on_iterate) {
  return smacof(lsmds_distances(graph, P, options), P, options, on_iterate);
}

}  // namespace unfold
