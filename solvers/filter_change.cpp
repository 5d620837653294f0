#include "solvers/filter_change.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <cmath>
#include <future>
#include <memory>
#include <vector>

#include "core/errors.h"
#include "mesh/best_rotations.h"
#include "mesh/cell_covariances.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {

namespace {

// The rebuild's Laplacian shifted by this times I: fixes the mean (to S2's,
// through the right side) and nothing else that counts.
constexpr double kShift = 1e-8;

// diagonal + sum over edges of w_e (e_i - e_j)(e_i - e_j)^T: every matrix here
// has this one pattern, so one symbolic analysis serves them all.
Eigen::SparseMatrix<double> laplacian_plus(const EdgeGraph& graph, const Eigen::VectorXd& w,
                                           double diagonal) {
  const int n = graph.num_vertices;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(4 * graph.num_edges() + n));
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int i = graph.edges(e, 0), j = graph.edges(e, 1);
    entries.insert(entries.end(), {{i, j, -w[e]}, {j, i, -w[e]}, {i, i, w[e]}, {j, j, w[e]}});
  }
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, diagonal);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

// L_P's weights, 1 / |p_i - p_j|^2 per edge.
Eigen::VectorXd inverse_squared_lengths(const EdgeGraph& graph, const Eigen::MatrixX3d& P) {
  Eigen::VectorXd squared(graph.num_edges());
  for (int e = 0; e < graph.num_edges(); ++e)
    squared[e] = (P.row(graph.edges(e, 0)) - P.row(graph.edges(e, 1))).squaredNorm();
  // Coinciding ends (clusters of a coarse graph may) weigh as a very short edge.
  const double floor = 1e-12 * (squared.size() > 0 ? squared.mean() : 0.0);
  return squared.cwiseMax(floor).cwiseInverse();
}

Rotations exponentials(const Eigen::MatrixX3d& omega) {
  Rotations R(static_cast<size_t>(omega.rows()));
  for (Eigen::Index i = 0; i < omega.rows(); ++i) {
    const double angle = omega.row(i).norm();
    R[size_t(i)] = angle > 0 ? Eigen::AngleAxisd(angle, omega.row(i).transpose() / angle).matrix()
                             : Eigen::Matrix3d::Identity();
  }
  return R;
}

}  // namespace

Eigen::MatrixX3d filter_change(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                               const Eigen::MatrixX3d& S1, const Eigen::MatrixX3d& S2,
                               const FilterChangeOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || S1.rows() != n || S2.rows() != n)
    throw UsageError("filter_change: P, S1 and S2 need one row per graph vertex");
  for (const double l : {options.rotation_length, options.stretch_length})
    if (!(l >= 0) || !std::isfinite(l))
      throw UsageError("filter_change: the lengths must be finite and >= 0");
  if (options.rotation_length == 0 && options.stretch_length == 0) return S2;

  Rotations D;
  best_rotations(graph, S1, S2, &D);
  Eigen::MatrixX3d omega(n, 3);
  for (int i = 0; i < n; ++i) {
    const Eigen::AngleAxisd turn(D[size_t(i)]);
    omega.row(i) = turn.angle() * turn.axis().transpose();
  }
  const Eigen::VectorXd inverse_squared = inverse_squared_lengths(graph, P);
  // F = (I + l^2 / 1.5 L_P)^-1: on a regular triangulation of spacing h,
  // sum_j (f_j - f_i) / h^2 is 1.5 Laplace(f), hence the 1.5. Its factor, or
  // none for length 0 (kept whole).
  const auto filter = [&graph, &inverse_squared](double length) {
    std::unique_ptr<SparseLdlt> F;
    if (length == 0) return F;
    const Eigen::SparseMatrix<double> A =
        laplacian_plus(graph, length * length / 1.5 * inverse_squared, 1.0);
    F = std::make_unique<SparseLdlt>();
    F->analyze(A);
    F->factorize(A);
    return F;
  };
  const auto filtered = [](const SparseLdlt* F, const Eigen::MatrixX3d& f) {
    if (!F) return f;
    Eigen::MatrixX3d x;
    F->solve(f, &x);
    return x;
  };
  // The three factorizations are independent, each on one thread: the two
  // filters' beside the rebuild's (david0's surface: the stage 0.34 -> 0.23 s).
  std::future<Eigen::MatrixX3d> omega_filtered = std::async(
      std::launch::async, [&] { return filtered(filter(options.rotation_length).get(), omega); });
  std::future<std::unique_ptr<SparseLdlt>> stretch_filter =
      std::async(std::launch::async, filter, options.stretch_length);
  const Eigen::SparseMatrix<double> L =
      laplacian_plus(graph, Eigen::VectorXd::Ones(graph.num_edges()), kShift);
  SparseLdlt solver;
  solver.analyze(L);
  solver.factorize(L);
  // S1's cells turned by R give the right side, sum_j (R_i + R_j)/2 (s1_i - s1_j).
  const CellRestEdges cells =
      cell_rest_edges(graph, S1, std::vector<double>(size_t(graph.num_edges()), 1.0));
  auto rebuild = [&](const Rotations& R) {
    Eigen::MatrixX3d b = kShift * S2;
    add_rotated_rest_edges(graph, cells, R, 0.5, &b);
    Eigen::MatrixX3d x;
    solver.solve(b, &x);
    return x;
  };
  const Eigen::MatrixX3d stretch = S2 - rebuild(D);
  const Eigen::MatrixX3d turned = rebuild(exponentials(omega_filtered.get()));
  return turned + filtered(stretch_filter.get().get(), stretch);
}

}  // namespace unfold
