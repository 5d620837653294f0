#include "solvers/arap_solve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "geometry/best_rotation.h"
#include "geometry/rotations.h"
#include "mesh/cell_covariances.h"
#include "solvers/anderson_acceleration.h"
#include "solvers/arap_multigrid.h"
#include "solvers/lbfgs_direction.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {
namespace {

// Cells from which a fit's sweeps run in parallel: a cell's rotation and
// right side cost enough that two threads pay off on a small animal's mesh
// (wolf0's 4.4k: its anchored steps' 74 fits 59 -> 36 ms), far below
// kMinParallelRows.
constexpr int kMinParallelCells = 1024;

// L-BFGS steps: halvings of a step that does not lower the energy enough
// before the plain step is taken instead.
constexpr int kMaxHalvings = 3;
// With a multigrid, halvings of the plain step (a descent direction, not a
// local-global step) before the steps count as converged.
constexpr int kMaxPlainHalvings = 10;
// L-BFGS steps: the initial inverse Hessian is scaled by the global matrix's
// curvature along the last step over the energy's, s.(L + A) s / s.y, kept in
// [1, this]. Rotations held, L + A is stiffer than the energy along a thin
// part's bending (2-14x on cat0's ears), so unscaled steps fall short there.
// Measured caps of 4, 10 and 1000: to convergence 67, 71 and 74 steps on cat0
// (90 unscaled), 103, 98 and 98 on david0 (123); 4 takes the fewest energy
// evaluations, 76 and 114 (docs/performance.md, the anchored steps' convergence).
constexpr double kMaxInitialScale = 4;

// Edge factors: none, or one finite positive number per edge.
void check_edge_factors(const EdgeGraph& graph, const ArapSolveOptions& options,
                        const std::string& caller) {
  const auto& f = options.edge_factors;
  if (f.empty()) return;
  bool ok = f.size() == size_t(graph.num_edges());
  for (const double x : f) ok = ok && std::isfinite(x) && x > 0;
  if (!ok)
    throw UsageError(caller + ": edge_factors needs one finite factor > 0 per edge (" +
                     std::to_string(graph.num_edges()) + "), got " + std::to_string(f.size()));
}

// Per edge of the graph: 1, or 1 / rest length scaled to mean 1 (the mesh's own
// stiffness, before any edge factors).
std::vector<double> length_weights(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                   const ArapSolveOptions& options) {
  std::vector<double> w(size_t(graph.num_edges()), 1.0);
  if (options.inverse_length_weights && graph.num_edges() > 0) {
    double sum = 0;
    for (int e = 0; e < graph.num_edges(); ++e) {
      // Coincident rest positions (a degenerate input) weigh as the shortest edge does.
      w[size_t(e)] = 1 / std::max((P.row(graph.edges(e, 0)) - P.row(graph.edges(e, 1))).norm(),
                                  std::numeric_limits<double>::min());
      sum += w[size_t(e)];
    }
    for (double& x : w) x *= graph.num_edges() / sum;
  }
  return w;
}

// The steps' weights: the length weights times the options' edge factors, if any.
void apply_edge_factors(const ArapSolveOptions& options, std::vector<double>* w) {
  for (size_t e = 0; e < options.edge_factors.size(); ++e) (*w)[e] *= options.edge_factors[e];
}

// arap_anchor_weights (m >= 0 free rows), w the length weights.
Eigen::VectorXd anchor_weights(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                               const std::vector<double>& w, const ArapSolveOptions& options) {
  const int m = graph.num_vertices - options.num_fixed;
  Eigen::VectorXd a = Eigen::VectorXd::Constant(m, options.anchor);
  if (!options.anchor_by_stiffness || m == 0) return a;
  Eigen::VectorXd k = Eigen::VectorXd::Zero(m);
  for (int i = options.num_fixed; i < graph.num_vertices; ++i)
    for (int j = graph.offsets[size_t(i)]; j < graph.offsets[size_t(i) + 1]; ++j)
      k(i - options.num_fixed) += w[size_t(graph.neighbor_edge[size_t(j)])] *
                                  (P.row(i) - P.row(graph.neighbors[size_t(j)])).squaredNorm();
  const double mean = k.mean();
  if (mean > 0) a.array() *= k.array() / mean;
  return a;
}

// arap_global_matrix with the edge weights computed already (m >= 1 free rows):
// the free vertices' block of the graph Laplacian (L_ij = -w_ij, L_ii = sum_j
// w_ij over every neighbour, held ones too: their edges go to the right side),
// plus the anchor. Assembled column by column from the graph's ascending
// neighbour lists, in parallel: a sort of triplets took 0.3 s at 196k tet
// vertices. Each diagonal sums its edges in the graph's edge order and every
// edge keeps its entry even at weight 0, as a triplet assembly would.
Eigen::SparseMatrix<double> free_block(const EdgeGraph& graph, const std::vector<double>& weights,
                                       const Eigen::VectorXd& anchor,
                                       const ArapSolveOptions& options) {
  const int num_fixed = options.num_fixed, m = graph.num_vertices - num_fixed;
  const bool uniform = !options.inverse_length_weights && options.edge_factors.empty();
  const bool anchored = options.anchor > 0;
  // A diagonal entry: always with uniform weights (the degree, 0 included) or
  // an anchor, else where the vertex has an edge.
  const auto has_diagonal = [&](int i) {
    return uniform || anchored || graph.offsets[size_t(i) + 1] > graph.offsets[size_t(i)];
  };
  Eigen::SparseMatrix<double> L(m, m);
  int* outer = L.outerIndexPtr();
  outer[0] = 0;
  for (int c = 0; c < m; ++c) {
    const int i = c + num_fixed;
    int entries = has_diagonal(i) ? 1 : 0;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      if (graph.neighbors[size_t(k)] >= num_fixed) ++entries;
    outer[c + 1] = outer[c] + entries;
  }
  L.resizeNonZeros(outer[m]);
  int* inner = L.innerIndexPtr();
  double* value = L.valuePtr();
#pragma omp parallel for schedule(static) if (m >= kMinParallelRows)
  for (int c = 0; c < m; ++c) {
    const int i = c + num_fixed;
    const bool diagonal_entry = has_diagonal(i);
    int slot = outer[c], diagonal_slot = -1;
    double diagonal = 0;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const double w = uniform ? 1.0 : weights[size_t(graph.neighbor_edge[size_t(k)])];
      diagonal += w;
      if (j > i && diagonal_entry && diagonal_slot < 0) diagonal_slot = slot++;
      if (j < num_fixed) continue;
      inner[slot] = j - num_fixed;
      value[slot++] = -w;
    }
    if (diagonal_entry && diagonal_slot < 0) diagonal_slot = slot++;
    if (diagonal_slot >= 0) {
      inner[diagonal_slot] = c;
      value[diagonal_slot] = anchored ? diagonal + anchor(c) : diagonal;
    }
  }
  return L;
}

std::unique_ptr<SparseLdlt> factorize_free_block(const Eigen::SparseMatrix<double>& L) {
  // L is positive definite (every free vertex reaches a held one): supernodal
  // LL^T, 3-4x faster to factorize than LDL^T on a 68k-vertex tet mesh.
  auto ldlt = std::make_unique<SparseLdlt>(SparseLdlt::Backend::kCholmodCholesky);
  ldlt->analyze(L);
  try {
    ldlt->factorize(L);
  } catch (const NumericalError&) {
    throw NumericalError("ARAP: some free vertex is not connected to a held one");
  }
  return ldlt;
}

}  // namespace

Eigen::SparseMatrix<double> arap_global_matrix(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                               const ArapSolveOptions& options,
                                               const std::string& caller) {
  const int n = graph.num_vertices, num_fixed = options.num_fixed;
  if (P.rows() != n || num_fixed < 1 || num_fixed >= n)
    throw UsageError(caller + ": need P with one row per graph vertex and 1 to n - 1 held");
  check_edge_factors(graph, options, caller);
  std::vector<double> weights = length_weights(graph, P, options);
  const Eigen::VectorXd anchor = anchor_weights(graph, P, weights, options);
  apply_edge_factors(options, &weights);
  return free_block(graph, weights, anchor, options);
}

std::unique_ptr<SparseLdlt> arap_factorization(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                               const ArapSolveOptions& options) {
  return factorize_free_block(arap_global_matrix(graph, P, options, "arap_factorization"));
}

Eigen::VectorXd arap_anchor_weights(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                    const ArapSolveOptions& options) {
  const int n = graph.num_vertices;
  if (P.rows() != n || options.num_fixed < 1 || options.num_fixed > n)
    throw UsageError("arap_anchor_weights: need P with one row per graph vertex and 1 to n held");
  check_edge_factors(graph, options, "arap_anchor_weights");
  return anchor_weights(graph, P, length_weights(graph, P, options), options);
}

Eigen::MatrixX3d arap_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P, Eigen::MatrixX3d Q,
                            const ArapSolveOptions& options, const SparseLdlt* factor,
                            ArapSolveReport* report, const ArapMultigrid* multigrid) {
  const int n = graph.num_vertices, num_fixed = options.num_fixed, m = n - num_fixed;
  if (P.rows() != n || Q.rows() != n || num_fixed < 1 || num_fixed > n)
    throw UsageError("arap_solve: need P and Q with one row per graph vertex and 1 to n held");
  if (options.max_iterations < 0 || !(options.tolerance >= 0) || !(options.anchor >= 0) ||
      options.anderson < 0 || options.lbfgs < 0)
    throw UsageError(
        "arap_solve: max_iterations, tolerance, anchor, anderson and lbfgs must be >= 0");
  check_edge_factors(graph, options, "arap_solve");
  if (multigrid && (factor || multigrid->matrix.rows() != m))
    throw UsageError("arap_solve: a multigrid needs no factor and one row per free vertex");
  if (report) *report = {};
  if (m == 0 || options.max_iterations == 0) return Q;  // nothing to move: no factorization
  report_stage("ARAP steps, " + std::to_string(m) + " free vertices" +
               (options.anchor > 0 ? ", anchored" : ""));
  std::vector<double> weights = length_weights(graph, P, options);
  const Eigen::VectorXd anchor = anchor_weights(graph, P, weights, options);
  apply_edge_factors(options, &weights);
  std::unique_ptr<SparseLdlt> own;
  if (!factor && !multigrid) {
    own = factorize_free_block(free_block(graph, weights, anchor, options));
    factor = own.get();
  }
  const Eigen::MatrixX3d start = Q.bottomRows(m);
  // The right side's parts that do not change: the anchor, and the held neighbours.
  Eigen::MatrixX3d fixed_rhs = anchor.asDiagonal() * start;
#pragma omp parallel for schedule(static) if (m >= kMinParallelRows)
  for (int i = num_fixed; i < n; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      if (graph.neighbors[size_t(k)] < num_fixed)
        fixed_rhs.row(i - num_fixed) +=
            weights[size_t(graph.neighbor_edge[size_t(k)])] * Q.row(graph.neighbors[size_t(k)]);
  // The centroid first: inside the expression Eigen recomputes it per row
  // (O(n^2): 0.67 s at 33k vertices, per call).
  const Eigen::RowVector3d centroid = Q.colwise().mean();
  const double radius = std::sqrt((Q.rowwise() - centroid).rowwise().squaredNorm().mean());

  // The cells whose rotation or energy term moves with the free rows: the free
  // vertices and their held neighbours. With the surface held (interior
  // placement) that is a third of the tet mesh; the other cells' terms are a
  // constant the steps cannot change.
  std::vector<int> active;
  for (int i = 0; i < n; ++i) {
    bool moves = i >= num_fixed;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1] && !moves; ++k)
      moves = graph.neighbors[size_t(k)] >= num_fixed;
    if (moves) active.push_back(i);
  }
  const int num_active = int(active.size());
  const CellRestEdges rest = cell_rest_edges(graph, P, weights);

  // Per active cell, sum_j w_ij |p_i - p_j|^2: its energy's constant part.
  std::vector<double> rest_length(size_t(num_active), 0.0);
  for (int a = 0; a < num_active; ++a) {
    const int i = active[size_t(a)];
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      rest_length[size_t(a)] +=
          rest.weighted_edges.row(k).dot(P.row(i) - P.row(graph.neighbors[size_t(k)]));
  }

  // At X's best rotations R (per cell): B_i = sum_j w_ij (R_i + R_j)/2 (p_i - p_j), the
  // right side's part that changes (free rows), and the energy the steps lower,
  // 1/2 sum_i sum_{j in N_i} w_ij |x_i - x_j - R_i (p_i - p_j)|^2 + sum_i a_i |x_i - start_i|^2
  // (the active cells' terms: the others are constant): the local step minimises it
  // over R, the global step over the free rows (its gradient is 2 (L x - B) +
  // 2 a (x - start)), so plain steps never raise it. Each fit starts its
  // rotations from the last fit's (cells turn little between steps). A cell's
  // term is taken from the sweep that makes its covariance C_i = sum_j w_ij
  // (p_i - p_j) (x_i - x_j)^T: 1/2 (sum_j w_ij |x_i - x_j|^2 - 2 tr(R_i C_i) +
  // sum_j w_ij |p_i - p_j|^2), so the second sweep (B, the neighbours' rotations)
  // runs over the free rows alone.
  Rotations R(size_t(n), Eigen::Matrix3d::Identity());
  bool warm = false;
  Eigen::MatrixX3d B(m, 3);
  RowMatrixX3d x_rows;
  // L-BFGS steps: where fit writes half the energy's gradient over the free rows,
  // sum_j w_ij (x_i - x_j) + a_i (x_i - start_i) - B_i (the neighbours held or
  // free; the global step solves it = 0 with B held); null: not wanted.
  Eigen::MatrixX3d* half_gradient = nullptr;
  const auto fit = [&](const Eigen::MatrixX3d& X) {
    x_rows = X;
    double energy = 0;
#pragma omp parallel for schedule(static) reduction(+ : energy) if (num_active >= kMinParallelCells)
    for (int first = 0; first < num_active; first += kRotationPacket) {
      Eigen::Matrix3d s[kRotationPacket];
      const Eigen::Matrix3d* cov[kRotationPacket];
      Eigen::Matrix3d* rotation[kRotationPacket];
      double lengths[kRotationPacket];  // sum_j w_ij (|x_i - x_j|^2 + |p_i - p_j|^2)
      int count = 0;
      for (int a = first; a < std::min(num_active, first + kRotationPacket); ++a) {
        const int i = active[size_t(a)];
        if (graph.degree(i) == 0) continue;
        // sum_j e_ij (x_i - x_j)^T
        Eigen::Matrix3d& c = s[count];
        c = rest.weighted_laplacian_rest.row(i).transpose() * x_rows.row(i);
        double length = rest_length[size_t(a)];
        for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
          const auto xj = x_rows.row(graph.neighbors[size_t(k)]);
          c.noalias() -= rest.weighted_edges.row(k).transpose() * xj;
          length +=
              weights[size_t(graph.neighbor_edge[size_t(k)])] * (x_rows.row(i) - xj).squaredNorm();
        }
        lengths[count] = length;
        cov[count] = &c;
        rotation[count++] = &R[size_t(i)];
      }
      if (warm) {
        best_rotations_from_guesses(cov, rotation, count);
      } else {
        for (int c = 0; c < count; ++c) *rotation[c] = best_rotation(*cov[c]);
      }
      for (int c = 0; c < count; ++c)
        energy += 0.5 * lengths[c] - (rotation[c]->cwiseProduct(cov[c]->transpose())).sum();
    }
    warm = true;
#pragma omp parallel for schedule(static) if (m >= kMinParallelCells)
    for (int i = num_fixed; i < n; ++i) {
      // sum_j (R_i + R_j)/2 w_ij (p_i - p_j) = (R_i (L_w P)_i + sum_j R_j w_ij (p_i - p_j)) / 2
      Eigen::Vector3d b = R[size_t(i)] * rest.weighted_laplacian_rest.row(i).transpose();
      for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
        b.noalias() +=
            R[size_t(graph.neighbors[size_t(k)])] * rest.weighted_edges.row(k).transpose();
      B.row(i - num_fixed) = 0.5 * b.transpose();
      if (half_gradient) {
        Eigen::RowVector3d r = anchor(i - num_fixed) * (x_rows.row(i) - start.row(i - num_fixed)) -
                               0.5 * b.transpose();
        for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
          r += weights[size_t(graph.neighbor_edge[size_t(k)])] *
               (x_rows.row(i) - x_rows.row(graph.neighbors[size_t(k)]));
        half_gradient->row(i - num_fixed) = r;
      }
    }
    return energy + anchor.dot((X.bottomRows(m) - start).rowwise().squaredNorm());
  };
  Eigen::MatrixX3d g, g_next;  // L-BFGS: half gradients at the iterate and the trial
  if (options.lbfgs > 0) {
    g.resize(m, 3);
    g_next.resize(m, 3);
    half_gradient = &g;
  }
  double level = fit(Q);
  Eigen::MatrixX3d x;  // each step's start (storage reused)
  int it = 0;
  bool converged = false;
  if (options.lbfgs > 0) {
    const LbfgsDirection::InitialInverse global_solve = [&](const Eigen::MatrixX3d& q,
                                                            Eigen::MatrixX3d* r) {
      if (multigrid)
        arap_multigrid_vcycle(*multigrid, q, r);
      else
        factor->solve(q, r);
    };
    LbfgsDirection lbfgs(options.lbfgs);
    Eigen::MatrixX3d d;
    // B at the last iterate: g' - g = (L + A) s - (B' - B) gives s.(L + A) s
    // without a product with the matrix.
    Eigen::MatrixX3d B_before = B;
    half_gradient = &g_next;
    while (it < options.max_iterations) {
      ++it;
      report_step(it, options.max_iterations);
      x = Q.bottomRows(m);
      double energy = 0;
      // The quasi-Newton step, halved until it lowers the energy enough (Armijo);
      // after kMaxHalvings the plain step (the history forgotten).
      lbfgs.direction(g, global_solve, &d);
      // Only the direction taken whole (no halving) counts towards convergence:
      // a step halved short of it, or the plain step after the history is
      // dropped (a local-global step, short where it crawls: david11's stopped
      // at 91 steps, 4.6 % above its converged E_rig), says nothing of the minimum.
      int halvings = 0;
      for (int plain_halvings = 0;; ++halvings) {
        Q.bottomRows(m) = x + d;
        energy = fit(Q);
        if (energy <= level + 2e-4 * g.reshaped().dot(d.reshaped())) break;
        if (lbfgs.size() == 0) {
          // A plain step by the factor is a local-global step, which never raises
          // the energy; one by a V-cycle can overshoot, so it is halved as well.
          if (!multigrid || plain_halvings == kMaxPlainHalvings) break;
          d *= 0.5;
          ++plain_halvings;
        } else if (halvings < kMaxHalvings) {
          d *= 0.5;
        } else {
          lbfgs.reset();
          lbfgs.direction(g, global_solve, &d);
        }
      }
      if (!(energy < level)) {  // converged as far as rounding lets it tell
        Q.bottomRows(m) = x;
        converged = true;
        break;
      }
      level = energy;
      if (lbfgs.update(d, g_next, g)) {
        const double sy = lbfgs.newest_curvature();
        lbfgs.scale_initial_inverse(std::clamp(
            (sy + d.reshaped().dot((B - B_before).reshaped())) / sy, 1.0, kMaxInitialScale));
      }
      B_before = B;
      g.swap(g_next);
      if (d.rowwise().norm().maxCoeff() <= options.tolerance * radius && halvings == 0) {
        converged = true;
        break;
      }
    }
  } else {
    const bool accelerate = options.anderson > 0;
    AndersonAcceleration anderson(std::max(1, options.anderson));
    // The steps' right side, solution and extrapolation: storage reused.
    Eigen::MatrixX3d rhs, free, extrapolated;
    while (it < options.max_iterations) {
      ++it;
      report_step(it, options.max_iterations);
      // d/dq_i of the energy = 0 for the free rows, R held.
      rhs = fixed_rhs + B;
      if (multigrid)
        arap_multigrid_solve(*multigrid, rhs, &free);
      else
        factor->solve(rhs, &free);
      const double step = (free - Q.bottomRows(m)).rowwise().norm().maxCoeff();
      x = Q.bottomRows(m);
      bool plain = !accelerate;
      double energy = 0;
      if (accelerate) {
        extrapolated.resize(m, 3);
        anderson.next(x.reshaped(), free.reshaped(), extrapolated.reshaped());
        Q.bottomRows(m) = extrapolated;
        energy = fit(Q);
        if (!(energy < level)) {
          anderson.reset();
          plain = true;
        }
      }
      converged = step <= options.tolerance * radius;
      const bool last = converged || it == options.max_iterations;
      if (plain) {
        Q.bottomRows(m) = free;
        if (last) break;  // no rotations needed after it
        energy = fit(Q);
        // A plain step that does not lower the energy: converged as far as
        // rounding lets it tell; keep the lower iterate.
        if (!(energy < level)) {
          Q.bottomRows(m) = x;
          converged = true;
          break;
        }
      }
      level = energy;
      if (last) break;
    }
  }
  if (report) *report = {it, converged};
  report_detail([&](std::ostream& line) {
    line << "ARAP: " << it << " steps, " << m << " free vertices, anchor " << options.anchor
         << (options.lbfgs > 0 ? ", L-BFGS " : ", Anderson ")
         << (options.lbfgs > 0 ? options.lbfgs : options.anderson) << ", energy " << level;
  });
  return Q;
}

}  // namespace unfold
