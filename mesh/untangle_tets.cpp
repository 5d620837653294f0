#include "mesh/untangle_tets.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "core/parallel.h"
#include "mesh/tet_volumes.h"

namespace unfold {
namespace {

// The volume a mended tet gets, as a share of its rest volume: enough that a
// roundoff-sized move of a neighbour does not flip it again, little enough that
// a sliver's corners move a small fraction of an edge.
constexpr double kTargetShare = 0.1;

// The gradient of tet_volume with respect to each corner (rows). The volume
// term's preconditioner (energies/volume_energy.cpp) writes the first row
// directly; here it is minus the sum of the others, which the figures in
// docs/results were made with.
Eigen::Matrix<double, 4, 3> volume_gradient(const Eigen::Matrix<double, 4, 3>& x) {
  const Eigen::RowVector3d a = x.row(0), b = x.row(1), c = x.row(2), d = x.row(3);
  Eigen::Matrix<double, 4, 3> g;
  g.row(1) = (c - a).cross(d - a) / 6.0;
  g.row(2) = (d - a).cross(b - a) / 6.0;
  g.row(3) = (b - a).cross(c - a) / 6.0;
  g.row(0) = -(g.row(1) + g.row(2) + g.row(3));
  return g;
}

}  // namespace

UntangleReport untangle_tets(const Eigen::MatrixX3d& made, const Eigen::MatrixX3d& rest,
                             const Eigen::MatrixX4i& T, const UntangleOptions& options,
                             Eigen::MatrixX3d* Q, const Eigen::MatrixXi* faces) {
  const Eigen::Index n = made.rows();
  if (rest.rows() != n || Q->rows() != n)
    throw UsageError("untangle_tets: made, rest and Q need the same rows, got " +
                     std::to_string(n) + ", " + std::to_string(rest.rows()) + " and " +
                     std::to_string(Q->rows()));
  if (T.size() > 0 && (T.minCoeff() < 0 || T.maxCoeff() >= n))
    throw UsageError("untangle_tets: a tet corner is not one of the " + std::to_string(n) +
                     " vertices");
  if (faces && faces->size() > 0 && (faces->minCoeff() < 0 || faces->maxCoeff() >= n))
    throw UsageError("untangle_tets: a face's vertex is not one of the " + std::to_string(n) +
                     " vertices");
  if (options.sweeps < 0 || !(options.max_move >= 0) || !std::isfinite(options.max_move))
    throw UsageError("untangle_tets: sweeps must be >= 0 and max_move finite and >= 0");
  const Eigen::Index m = T.rows();
  const Eigen::VectorXd made_volume = tet_volumes(made, T);
  const Eigen::VectorXd target = kTargetShare * tet_volumes(rest, T).cwiseAbs();
  // h: the shortest rest edge at each vertex, of a tet or a face.
  Eigen::VectorXd h = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  const auto shortest = [&](const auto& rows) {
    for (Eigen::Index r = 0; r < rows.rows(); ++r)
      for (Eigen::Index i = 0; i < rows.cols(); ++i)
        for (Eigen::Index j = i + 1; j < rows.cols(); ++j) {
          const double l = (rest.row(rows(r, i)) - rest.row(rows(r, j))).norm();
          h[rows(r, i)] = std::min(h[rows(r, i)], l);
          h[rows(r, j)] = std::min(h[rows(r, j)], l);
        }
  };
  shortest(T);
  if (faces) shortest(*faces);
  const auto corners = [&](Eigen::Index t) {
    Eigen::Matrix<double, 4, 3> x;
    for (int k = 0; k < 4; ++k) x.row(k) = Q->row(T(t, k));
    return x;
  };
  // The tet's volume with the sign it was made with: positive when upright.
  const auto upright_volume = [&](Eigen::Index t) {
    return made_volume[t] > 0 ? tet_volume(corners(t)) : -tet_volume(corners(t));
  };
  // Each tet's upright volume as last evaluated (infinite: made flat, never mended).
  Eigen::VectorXd now(m);
  int inverted = 0;
#pragma omp parallel for schedule(static) reduction(+ : inverted) if (m >= kMinParallelRows)
  for (Eigen::Index t = 0; t < m; ++t) {
    now[t] = made_volume[t] != 0 ? upright_volume(t) : std::numeric_limits<double>::infinity();
    inverted += now[t] <= 0;
  }
  UntangleReport report;
  report.inverted_before = report.inverted_after = inverted;
  // The tets at each vertex (CSR): a pass evaluates again only the tets whose
  // corners it moved, so it costs what it mends, not the mesh.
  std::vector<int> first(size_t(n) + 1, 0), tets_at(size_t(4 * m));
  for (Eigen::Index t = 0; t < m; ++t)
    for (int k = 0; k < 4; ++k) ++first[size_t(T(t, k)) + 1];
  for (Eigen::Index i = 0; i < n; ++i) first[size_t(i) + 1] += first[size_t(i)];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (Eigen::Index t = 0; t < m; ++t)
    for (int k = 0; k < 4; ++k) tets_at[size_t(fill[size_t(T(t, k))]++)] = int(t);

  std::vector<int> below;  // the tets below their target, in row order
  for (Eigen::Index t = 0; t < m; ++t)
    if (now[t] < target[t]) below.push_back(int(t));
  std::vector<char> vertex_moved(size_t(n), 0), seen(size_t(m), 0);
  std::vector<int> moved_vertices, evaluated;
  const Eigen::MatrixX3d start = *Q;
  while (report.sweeps < options.sweeps && report.inverted_after > 0) {
    ++report.sweeps;
    for (const int t : below) {
      // Evaluated again: a neighbour mended earlier in the pass may have moved it.
      const Eigen::Matrix<double, 4, 3> x = corners(t);
      const double sign = made_volume[t] > 0 ? 1.0 : -1.0;
      const double v = sign * tet_volume(x);
      if (v >= target[t]) continue;
      const Eigen::Matrix<double, 4, 3> g = sign * volume_gradient(x);
      double norm = 0;
      for (int k = 0; k < 4; ++k) norm += h[T(t, k)] * h[T(t, k)] * g.row(k).squaredNorm();
      if (!(norm > 0)) continue;
      const double lambda = (target[t] - v) / norm;
      for (int k = 0; k < 4; ++k) {
        const int i = T(t, k);
        Q->row(i) += lambda * h[i] * h[i] * g.row(k);
        const Eigen::RowVector3d moved = Q->row(i) - start.row(i);
        const double allowed = options.max_move * h[i];
        if (moved.norm() > allowed) Q->row(i) = start.row(i) + moved * (allowed / moved.norm());
        if (!vertex_moved[size_t(i)]) moved_vertices.push_back(i);
        vertex_moved[size_t(i)] = 1;
      }
    }
    // The tets at the moved vertices evaluated again; the others are as they
    // were (those below their target whose corners did not move cannot be mended).
    below.clear();
    for (const int i : moved_vertices) {
      vertex_moved[size_t(i)] = 0;
      for (int k = first[size_t(i)]; k < first[size_t(i) + 1]; ++k) {
        const int t = tets_at[size_t(k)];
        if (seen[size_t(t)] || made_volume[t] == 0) continue;
        seen[size_t(t)] = 1;
        evaluated.push_back(t);
        const double v = upright_volume(t);
        report.inverted_after += int(v <= 0) - int(now[t] <= 0);
        now[t] = v;
        if (v < target[t]) below.push_back(t);
      }
    }
    moved_vertices.clear();
    for (const int t : evaluated) seen[size_t(t)] = 0;
    evaluated.clear();
    std::sort(below.begin(), below.end());
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const double moved = (Q->row(i) - start.row(i)).norm();
    if (moved == 0) continue;
    ++report.moved_vertices;
    report.largest_move = std::max(report.largest_move, moved / h[i]);
  }
  return report;
}

}  // namespace unfold
