#include "solvers/prolong_surface_solve.h"

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/parallel.h"
#include "geometry/best_rotation.h"
#include "mesh/locality_order.h"
#include "mesh/permute_edge_graph.h"
#include "solvers/projected_cg.h"
#include "solvers/smoothed_aggregation.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {
namespace {

constexpr double kAnchor = 0.01;    // mu, against unit edge weights
constexpr int kSmoothingSteps = 3;  // integrations after the first, each vertex its own similarity
// CG's relative residual: the tets made of the result then differ from the
// factor's in about 1 in 40,000 (186k-vertex scan, docs/performance.md).
constexpr double kCgTolerance = 1e-6;

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

// L + mu I, L the uniform graph Laplacian: both triangles, column by column
// from the graph's ascending neighbour lists (the factor reads the lower one,
// CG both).
Eigen::SparseMatrix<double> carry_matrix(const EdgeGraph& g) {
  const int n = g.num_vertices;
  Eigen::SparseMatrix<double> M(n, n);
  int* outer = M.outerIndexPtr();
  for (int i = 0; i <= n; ++i) outer[i] = g.offsets[size_t(i)] + i;
  M.resizeNonZeros(outer[n]);
  int* inner = M.innerIndexPtr();
  double* value = M.valuePtr();
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int i = 0; i < n; ++i) {
    int slot = outer[i], diagonal_slot = -1;
    double diagonal = kAnchor;  // summed as the factor's was: the same bits
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      if (j > i && diagonal_slot < 0) diagonal_slot = slot++;
      inner[slot] = j;
      value[slot++] = -1;
      diagonal += 1;
    }
    if (diagonal_slot < 0) diagonal_slot = slot;
    inner[diagonal_slot] = i;
    value[diagonal_slot] = diagonal;
  }
  return M;
}

// The carry on a graph and rest positions whose vertex i is in cluster
// cluster[i], its solves by the factor of L + mu I or, with `iterative`, by
// CG preconditioned with its AMG hierarchy, each solve from the last solution.
Eigen::MatrixX3d carry(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                       const std::vector<int>& cluster, const SurfaceCoarsening& coarsening,
                       const Eigen::MatrixX3d& Sc, const std::vector<Eigen::Matrix3d>& A,
                       bool iterative) {
  const int n = graph.num_vertices;
  // Every vertex starts with its cluster's similarity; the integrations after
  // the first fit each vertex's own to its 1-ring, which smooths the seams
  // between clusters (as-similar-as-possible steps).
  std::vector<Eigen::Matrix3d> B(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) B[size_t(i)] = A[size_t(cluster[size_t(i)])];
  const Eigen::SparseMatrix<double> M = carry_matrix(graph);
  SparseLdlt ldlt(SparseLdlt::Backend::kCholmodCholesky);
  AmgData amg;
  if (iterative) {
    AmgOptions options;
    options.gershgorin_lambda_max = true;  // a positive definite preconditioner for CG
    amg_precomputation(M, options, &amg);
  } else {
    ldlt.analyze(M);
    ldlt.factorize(M);
  }
  // Where each vertex's cluster puts it: the anchor's target, and CG's start.
  Eigen::MatrixX3d placed(n, 3);
  for (int i = 0; i < n; ++i) {
    const int c = cluster[size_t(i)];
    placed.row(i) = Sc.row(c) + (P.row(i) - coarsening.V.row(c)) * A[size_t(c)].transpose();
  }
  Eigen::MatrixX3d S = placed;
  RowMatrixX3d y = placed;
  CgOptions cg;
  cg.tolerance = kCgTolerance;
  cg.zero_mean = false;
  CgWorkspace work;
  for (int step = 0; step <= kSmoothingSteps; ++step) {
    if (step > 0) B = best_similarities(graph, P, S);
    Eigen::MatrixX3d b = kAnchor * placed;
    for (int e = 0; e < graph.num_edges(); ++e) {
      const int i = graph.edges(e, 0), j = graph.edges(e, 1);
      const Eigen::RowVector3d v =
          (P.row(i) - P.row(j)) * (0.5 * (B[size_t(i)] + B[size_t(j)])).transpose();
      b.row(i) += v;
      b.row(j) -= v;
    }
    if (!iterative) {
      ldlt.solve(b, &S);
      continue;
    }
    const CgResult r = projected_cg(CsrView::of_symmetric(M), amg, RowMatrixX3d(b), &y, cg, &work);
    if (!r.converged)
      throw NumericalError("prolong_surface_solve: CG reached a relative residual of " +
                           std::to_string(r.relative_residual) + " in " +
                           std::to_string(r.iterations) + " iterations");
    S = y;
  }
  return S;
}

}  // namespace

Eigen::MatrixX3d prolong_surface_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const SurfaceCoarsening& coarsening,
                                       const Eigen::MatrixX3d& Sc, int iterative_from) {
  const int n = graph.num_vertices;
  if (P.rows() != n || int(coarsening.cluster_of.size()) != n || Sc.rows() != coarsening.V.rows() ||
      coarsening.graph.num_vertices != Sc.rows())
    throw UsageError("prolong_surface_solve: " + std::to_string(n) + " vertices, " +
                     std::to_string(P.rows()) + " rest positions, " +
                     std::to_string(coarsening.cluster_of.size()) + " cluster labels and " +
                     std::to_string(Sc.rows()) + " coarse positions for " +
                     std::to_string(coarsening.V.rows()) + " clusters");
  const std::vector<Eigen::Matrix3d> A = best_similarities(coarsening.graph, coarsening.V, Sc);
  Eigen::MatrixX3d S;
  if (n < iterative_from) {
    S = carry(graph, P, coarsening.cluster_of, coarsening, Sc, A, false);
  } else {
    // In locality order: CG's sweeps then read neighbours from cache.
    const std::vector<int> order = locality_order(P);
    std::vector<int> cluster(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k)
      cluster[size_t(k)] = coarsening.cluster_of[size_t(order[size_t(k)])];
    S.resize(n, 3);
    S(order, Eigen::all) = carry(permute_edge_graph(graph, order), P(order, Eigen::all), cluster,
                                 coarsening, Sc, A, true);
  }
  return S.rowwise() - S.colwise().mean();
}

}  // namespace unfold
