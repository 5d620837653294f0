#include "solvers/smoothed_aggregation.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "core/errors.h"
#include "core/parallel.h"
#include "solvers/sparse_product.h"

namespace unfold {
namespace {

// Aggregates of strongly connected nodes (Vanek et al.'s three passes): a node
// whose strong neighbours are all free starts an aggregate with them; a left-over
// node joins its strongest neighbour's aggregate of the first pass; what is still
// free forms aggregates with its free neighbours. Returns the count.
int aggregate(const RowSparse& A, double strength, std::vector<int>* aggregate_of) {
  const int n = int(A.rows());
  const Eigen::VectorXd diagonal = A.diagonal();
  const auto strong = [&](int i, const RowSparse::InnerIterator& it) {
    return it.col() != i &&
           std::abs(it.value()) > strength * std::sqrt(std::abs(diagonal[i] * diagonal[it.col()]));
  };
  std::vector<int>& agg = *aggregate_of;
  agg.assign(size_t(n), -1);
  int count = 0;
  for (int i = 0; i < n; ++i) {
    bool free = true;
    for (RowSparse::InnerIterator it(A, i); it && free; ++it)
      if (strong(i, it) && agg[size_t(it.col())] >= 0) free = false;
    if (!free || agg[size_t(i)] >= 0) continue;
    agg[size_t(i)] = count;
    for (RowSparse::InnerIterator it(A, i); it; ++it)
      if (strong(i, it)) agg[size_t(it.col())] = count;
    ++count;
  }
  const std::vector<int> first_pass = agg;
  for (int i = 0; i < n; ++i) {
    if (agg[size_t(i)] >= 0) continue;
    double best = 0;
    for (RowSparse::InnerIterator it(A, i); it; ++it)
      if (strong(i, it) && first_pass[size_t(it.col())] >= 0 && std::abs(it.value()) > best) {
        best = std::abs(it.value());
        agg[size_t(i)] = first_pass[size_t(it.col())];
      }
  }
  for (int i = 0; i < n; ++i) {
    if (agg[size_t(i)] >= 0) continue;
    agg[size_t(i)] = count;
    for (RowSparse::InnerIterator it(A, i); it; ++it)
      if (strong(i, it) && agg[size_t(it.col())] < 0) agg[size_t(it.col())] = count;
    ++count;
  }
  return count;
}

// Largest eigenvalue of D^-1 A: a few power steps in the D inner product (a
// lower estimate, raised by 10 %), capped by Gershgorin's bound; or that bound alone.
double estimate_lambda_max(const RowSparse& A, const Eigen::VectorXd& inverse_diagonal,
                           bool gershgorin_only) {
  const int n = int(A.rows());
  double gershgorin = 0;
  for (int i = 0; i < n; ++i) {
    double row = 0;
    for (RowSparse::InnerIterator it(A, i); it; ++it) row += std::abs(it.value());
    gershgorin = std::max(gershgorin, row * inverse_diagonal[i]);
  }
  if (gershgorin_only) return gershgorin;
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = unit(random);
  double estimate = 0;
  for (int k = 0; k < 15; ++k) {
    const Eigen::VectorXd Av = A * v;
    const double vDv = v.dot(v.cwiseQuotient(inverse_diagonal));
    if (!(vDv > 0)) break;
    estimate = v.dot(Av) / vDv;
    v = inverse_diagonal.cwiseProduct(Av);
    v /= v.norm();
  }
  return std::min(gershgorin, 1.1 * estimate);
}

void build_level(AmgLevel* level, bool gershgorin_lambda_max) {
  const int n = int(level->A.rows());
  level->inverse_diagonal.resize(n);
  for (int i = 0; i < n; ++i) {
    const double d = level->A.coeff(i, i);
    if (!(d > 0))
      throw UsageError("amg_precomputation: diagonal entry " + std::to_string(i) +
                       " is not positive");
    level->inverse_diagonal[i] = 1 / d;
  }
  level->lambda_max = estimate_lambda_max(level->A, level->inverse_diagonal, gershgorin_lambda_max);
}

// Chebyshev polynomial smoothing of A x = b with the Jacobi preconditioner
// D^-1, damping the eigenvalues of D^-1 A in [lambda_max / ratio, lambda_max]
// (Saad's three-term recurrence). A polynomial in D^-1 A keeps the V-cycle
// symmetric when the same smoother runs before and after the coarse correction.
template <typename Scalar>
void chebyshev(const AmgLevelOf<Scalar>& level, const AmgOptions& options,
               const RowMatrixX3<Scalar>& b, RowMatrixX3<Scalar>* x, bool zero_initial) {
  const CsrViewOf<Scalar> A(level.A);
  const int n = A.rows;
  const double upper = level.lambda_max, lower = upper / options.smoothing_ratio;
  const double theta = (upper + lower) / 2, delta = (upper - lower) / 2, sigma = theta / delta;
  double rho = 1 / sigma;
  RowMatrixX3<Scalar>& r = level.r;
  RowMatrixX3<Scalar>& d = level.d;
  const auto& dinv = level.inverse_diagonal;
  // First step: d = D^-1 r / theta with r = b - A x (= b from x = 0), x += d.
  if (zero_initial) {
    d.resize(n, 3);
    x->resize(n, 3);
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
    for (int i = 0; i < n; ++i) x->row(i) = d.row(i) = (dinv[i] / Scalar(theta)) * b.row(i);
  } else {
    residual(A, b, *x, &r);
    d.resize(n, 3);
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
    for (int i = 0; i < n; ++i) {
      d.row(i) = (dinv[i] / Scalar(theta)) * r.row(i);
      x->row(i) += d.row(i);
    }
  }
  for (int k = 2; k <= options.smoothing_degree; ++k) {
    residual(A, k == 2 && zero_initial ? b : r, d, &r);  // r -= A d (r = b - A d the first time)
    const double rho_next = 1 / (2 * sigma - rho);
    const Scalar keep = Scalar(rho_next * rho), step = Scalar(2 * rho_next / delta);
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
    for (int i = 0; i < n; ++i) {
      d.row(i) = keep * d.row(i) + (step * dinv[i]) * r.row(i);
      x->row(i) += d.row(i);
    }
    rho = rho_next;
  }
}

// Inverse on the complement of the null space, eigenvalues at roundoff level
// dropped: the coarse Laplacian keeps the constant vector in its null space.
Eigen::MatrixXd pseudo_inverse(const Eigen::MatrixXd& A) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  const Eigen::VectorXd& values = eig.eigenvalues();
  const double cutoff = 1e-10 * values.cwiseAbs().maxCoeff();
  Eigen::VectorXd inverse(values.size());
  for (Eigen::Index k = 0; k < values.size(); ++k)
    inverse[k] = values[k] > cutoff ? 1 / values[k] : 0;
  return eig.eigenvectors() * inverse.asDiagonal() * eig.eigenvectors().transpose();
}

template <typename Scalar, typename Dense>
void vcycle(const std::vector<AmgLevelOf<Scalar>>& levels, const Dense& coarse_inverse,
            const AmgOptions& options, size_t l, const RowMatrixX3<Scalar>& b,
            RowMatrixX3<Scalar>* x) {
  if (l + 1 == levels.size()) {
    *x = coarse_inverse * b;
    return;
  }
  const AmgLevelOf<Scalar>& level = levels[l];
  const AmgLevelOf<Scalar>& coarse = levels[l + 1];
  chebyshev(level, options, b, x, true);
  residual(CsrViewOf<Scalar>(level.A), b, *x, &level.r);
  multiply(CsrViewOf<Scalar>(level.R), level.r, &coarse.b);
  vcycle(levels, coarse_inverse, options, l + 1, coarse.b, &coarse.x);
  multiply(CsrViewOf<Scalar>(level.P), coarse.x, &level.d);
  *x += level.d;
  chebyshev(level, options, b, x, false);
}

// The float copy of a level (its work blocks stay empty until used).
AmgLevelOf<float> single_precision_level(const AmgLevel& level) {
  AmgLevelOf<float> single;
  single.A = level.A.cast<float>();
  single.inverse_diagonal = level.inverse_diagonal.cast<float>();
  single.lambda_max = level.lambda_max;
  single.P = level.P.cast<float>();
  single.R = level.R.cast<float>();
  for (auto* M : {&single.A, &single.P, &single.R}) M->makeCompressed();  // for CsrViewOf
  return single;
}

constexpr int kReservedLevels = 64;  // more than a million-vertex mesh's 6-7

}  // namespace

void amg_precomputation(const Eigen::SparseMatrix<double>& M, const AmgOptions& options,
                        AmgData* data) {
  if (M.rows() != M.cols()) throw UsageError("amg_precomputation: matrix is not square");
  data->options = options;
  data->levels.clear();
  // Room for every level up front: Eigen's sparse matrices have no move
  // constructor, so a reallocation would copy the levels made so far (0.1-0.25 s
  // at 186k vertices).
  data->levels.reserve(size_t(std::clamp(options.max_levels, 1, kReservedLevels)));
  data->levels.emplace_back();
  data->levels.back().A = RowSparse(M).pruned();
  double nonzeros = 0;
  const double finest = double(data->levels.back().A.nonZeros());
  for (;;) {
    AmgLevel& level = data->levels.back();
    level.A.makeCompressed();
    build_level(&level, options.gershgorin_lambda_max);
    nonzeros += double(level.A.nonZeros());
    const int n = int(level.A.rows());
    if (n <= options.coarse_size || int(data->levels.size()) >= options.max_levels) break;
    std::vector<int> agg;
    const int nc = aggregate(level.A, options.strength, &agg);
    if (nc >= n * 9 / 10) break;  // no real coarsening left
    // Tentative prolongator: piecewise constant on aggregates (it carries the
    // constant vector, the Laplacian's null space, exactly), then one damped
    // Jacobi step (I - omega D^-1 A) smooths its basis functions.
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(size_t(n));
    for (int i = 0; i < n; ++i) t.emplace_back(i, agg[size_t(i)], 1.0);
    RowSparse P0(n, nc);
    P0.setFromTriplets(t.begin(), t.end());
    const double omega = 4.0 / (3.0 * level.lambda_max);
    const RowSparse AP0 = sparse_product(level.A, P0);
    const RowSparse DAP0 = level.inverse_diagonal.asDiagonal() * AP0;
    level.P = RowSparse(P0 - omega * DAP0).pruned();
    level.R = level.P.transpose();
    const RowSparse AP = sparse_product(level.A, level.P);
    const RowSparse RAP = sparse_product(level.R, AP);
    RowSparse coarse =
        RowSparse(0.5 * (RAP + RowSparse(RAP.transpose()))).pruned();  // exact symmetry
    data->levels.emplace_back();
    data->levels.back().A.swap(coarse);
  }
  data->operator_complexity = nonzeros / finest;
  data->coarse_inverse = pseudo_inverse(Eigen::MatrixXd(data->levels.back().A));
  data->single_levels.clear();
  if (options.single_precision) {
    data->single_levels.reserve(data->levels.size());
    for (const AmgLevel& level : data->levels)
      data->single_levels.push_back(single_precision_level(level));
    data->single_coarse_inverse = data->coarse_inverse.cast<float>();
  }
}

void amg_vcycle(const AmgData& data, const RowMatrixX3d& b, RowMatrixX3d* x) {
  if (data.single_levels.empty()) {
    vcycle(data.levels, data.coarse_inverse, data.options, 0, b, x);
    return;
  }
  // The finest level's own x and b blocks are free: the cycle uses each level's
  // r and d, and the coarser levels' x and b.
  const AmgLevelOf<float>& finest = data.single_levels.front();
  finest.b = b.cast<float>();
  vcycle(data.single_levels, data.single_coarse_inverse, data.options, 0, finest.b, &finest.x);
  *x = finest.x.cast<double>();
}

}  // namespace unfold
