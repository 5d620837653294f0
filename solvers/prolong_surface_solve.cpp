#include "solvers/prolong_surface_solve.h"

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "core/errors.h"
#include "geometry/best_rotation.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {
namespace {

constexpr double kAnchor = 0.01;    // mu, against unit edge weights
constexpr int kSmoothingSteps = 3;  // integrations after the first, each vertex its own similarity

// Each vertex's best similarity s R from its 1-ring in `rest` to its 1-ring in
// `now`: R by Kabsch, s = sum_j e_j . R d_j / sum_j |d_j|^2.
std::vector<Eigen::Matrix3d> best_similarities(const EdgeGraph& g, const Eigen::MatrixX3d& rest,
                                               const Eigen::MatrixX3d& now) {
  std::vector<Eigen::Matrix3d> A(size_t(g.num_vertices), Eigen::Matrix3d::Identity());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < g.num_vertices; ++i) {
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    double length2 = 0;
    for (int m = g.offsets[size_t(i)]; m < g.offsets[size_t(i) + 1]; ++m) {
      const int j = g.neighbors[size_t(m)];
      const Eigen::Vector3d d = (rest.row(j) - rest.row(i)).transpose();
      cov += d * (now.row(j) - now.row(i));
      length2 += d.squaredNorm();
    }
    if (!(length2 > 0)) continue;  // no neighbours (a one-cluster surface)
    const Eigen::Matrix3d R = best_rotation(cov);
    A[size_t(i)] = (R * cov).trace() / length2 * R;
  }
  return A;
}

}  // namespace

Eigen::MatrixX3d prolong_surface_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const SurfaceCoarsening& coarsening,
                                       const Eigen::MatrixX3d& Sc) {
  const int n = graph.num_vertices;
  if (P.rows() != n || int(coarsening.cluster_of.size()) != n || Sc.rows() != coarsening.V.rows() ||
      coarsening.graph.num_vertices != Sc.rows())
    throw UsageError("prolong_surface_solve: " + std::to_string(n) + " vertices, " +
                     std::to_string(P.rows()) + " rest positions, " +
                     std::to_string(coarsening.cluster_of.size()) + " cluster labels and " +
                     std::to_string(Sc.rows()) + " coarse positions for " +
                     std::to_string(coarsening.V.rows()) + " clusters");
  const std::vector<Eigen::Matrix3d> A = best_similarities(coarsening.graph, coarsening.V, Sc);
  const auto& cluster = coarsening.cluster_of;
  // Every vertex starts with its cluster's similarity; the integrations after
  // the first fit each vertex's own to its 1-ring, which smooths the seams
  // between clusters (as-similar-as-possible steps).
  std::vector<Eigen::Matrix3d> B(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) B[size_t(i)] = A[size_t(cluster[size_t(i)])];
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(n + graph.num_edges()));
  Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(n, kAnchor);
  for (int e = 0; e < graph.num_edges(); ++e) {
    diagonal[graph.edges(e, 0)] += 1;
    diagonal[graph.edges(e, 1)] += 1;
    // The lower triangle (edges(e, 1) > edges(e, 0)) is what the factor reads.
    entries.emplace_back(graph.edges(e, 1), graph.edges(e, 0), -1.0);
  }
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> M(n, n);
  M.setFromTriplets(entries.begin(), entries.end());
  SparseLdlt ldlt(SparseLdlt::Backend::kCholmodCholesky);
  ldlt.analyze(M);
  ldlt.factorize(M);
  Eigen::MatrixX3d anchor(n, 3);
  for (int i = 0; i < n; ++i) {
    const int c = cluster[size_t(i)];
    anchor.row(i) =
        kAnchor * (Sc.row(c) + (P.row(i) - coarsening.V.row(c)) * A[size_t(c)].transpose());
  }
  Eigen::MatrixX3d S;
  for (int step = 0; step <= kSmoothingSteps; ++step) {
    if (step > 0) B = best_similarities(graph, P, S);
    Eigen::MatrixX3d b = anchor;
    for (int e = 0; e < graph.num_edges(); ++e) {
      const int i = graph.edges(e, 0), j = graph.edges(e, 1);
      const Eigen::RowVector3d v =
          (P.row(i) - P.row(j)) * (0.5 * (B[size_t(i)] + B[size_t(j)])).transpose();
      b.row(i) += v;
      b.row(j) -= v;
    }
    ldlt.solve(b, &S);
  }
  return S.rowwise() - S.colwise().mean();
}

}  // namespace unfold
