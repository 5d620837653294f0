#include "solvers/lobpcg.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <random>

#include "core/errors.h"

namespace unfold {
namespace {

using Block = Eigen::MatrixXd;  // n x k, column-major: the Rayleigh-Ritz side

// B X for the diagonal B of the generalized problem (b empty: B = I).
Block times_b(const Eigen::VectorXd& b, const Block& X) {
  return b.size() ? Block(b.asDiagonal() * X) : X;
}

// Off the null vector 1 in the B inner product: x -= 1 (b^T x) / sum b.
void remove_means(const Eigen::VectorXd& b, Block* X) {
  if (b.size() == 0)
    X->rowwise() -= X->colwise().mean();
  else
    X->rowwise() -= (b.transpose() * *X) / b.sum();
}

// M X for an n x 3 block, through the row-major kernel.
Block apply(const CsrView& M, const Block& X) {
  RowMatrixX3d x = X, y;
  multiply(M, x, &y);
  return y;
}

// B-orthonormalizes the columns of X (and the same combination of MX) by the
// Cholesky factor of X^T B X; false when X is numerically rank-deficient.
bool orthonormalize(const Eigen::VectorXd& b, Block* X, Block* MX) {
  const Eigen::LLT<Eigen::MatrixXd> llt(X->transpose() * times_b(b, *X));
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd U = llt.matrixU();
  const Eigen::MatrixXd U_inverse =
      U.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(U.rows(), U.cols()));
  if (!U_inverse.allFinite()) return false;
  *X = *X * U_inverse;
  if (MX) *MX = *MX * U_inverse;
  return true;
}

// Rayleigh-Ritz on span(S): the 3 smallest Ritz values and their coefficient
// vectors (columns of *Y). False when the Gram matrix is not positive definite.
bool rayleigh_ritz(const Eigen::VectorXd& b, const Block& S, const Block& MS,
                   Eigen::Vector3d* values, Eigen::MatrixXd* Y) {
  Eigen::MatrixXd A = S.transpose() * MS, B = S.transpose() * times_b(b, S);
  A = 0.5 * (A + A.transpose()).eval();
  B = 0.5 * (B + B.transpose()).eval();
  if (Eigen::LLT<Eigen::MatrixXd>(B).info() != Eigen::Success) return false;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, B);
  if (eig.info() != Eigen::Success) return false;
  *values = eig.eigenvalues().head<3>();  // ascending
  *Y = eig.eigenvectors().leftCols<3>();
  return Y->allFinite();
}

}  // namespace

LobpcgResult lobpcg_smallest(const CsrView& M, const AmgData& preconditioner,
                             const LobpcgOptions& options, const Eigen::VectorXd& b) {
  const int n = M.rows;
  if (n < 12) throw UsageError("lobpcg_smallest: needs at least 12 rows");
  if (b.size() != 0 && (b.size() != n || !(b.minCoeff() > 0)))
    throw UsageError("lobpcg_smallest: B must have n positive diagonal entries");
  LobpcgResult result;
  std::mt19937_64 random(options.seed);
  std::normal_distribution<double> normal;
  Block X(n, 3);
  for (Eigen::Index i = 0; i < X.size(); ++i) X.data()[i] = normal(random);
  remove_means(b, &X);
  orthonormalize(b, &X, nullptr);
  Block MX = apply(M, X);
  Eigen::MatrixXd Y;
  rayleigh_ritz(b, X, MX, &result.values, &Y);
  X = X * Y;
  MX = MX * Y;
  Block P, MP;  // previous search directions, empty at first
  RowMatrixX3d r_rows, w_rows;
  for (;;) {
    const Block BX = times_b(b, X);
    const Block R = MX - BX * result.values.asDiagonal();
    result.relative_residual = R.col(0).norm() / (std::abs(result.values[0]) * BX.col(0).norm());
    result.converged = result.relative_residual <= options.tolerance;
    if (result.converged || result.iterations >= options.max_iterations) break;
    ++result.iterations;
    r_rows = R;
    amg_vcycle(preconditioner, r_rows, &w_rows);
    Block W = w_rows;
    remove_means(b, &W);
    W -= X * (BX.transpose() * W);               // keeps [X W] well conditioned near convergence
    if (!orthonormalize(b, &W, nullptr)) break;  // nothing new to add: X is as good as it gets
    Block MW = apply(M, W);
    const bool with_p = P.cols() == 3 && orthonormalize(b, &P, &MP);
    const int k = with_p ? 9 : 6;
    Block S(n, k), MS(n, k);
    S << X, W;
    MS << MX, MW;
    if (with_p) {
      S.rightCols<3>() = P;
      MS.rightCols<3>() = MP;
    }
    Eigen::Vector3d values;
    if (!rayleigh_ritz(b, S, MS, &values, &Y)) {
      if (!with_p) break;
      // Restart without the old directions (they became dependent).
      S.conservativeResize(n, 6);
      MS.conservativeResize(n, 6);
      if (!rayleigh_ritz(b, S, MS, &values, &Y)) break;
    }
    const Eigen::Index rest = S.cols() - 3;
    P = S.rightCols(rest) * Y.bottomRows(rest);
    MP = MS.rightCols(rest) * Y.bottomRows(rest);
    X = X * Y.topRows<3>() + P;
    MX = MX * Y.topRows<3>() + MP;
    result.values = values;
  }
  remove_means(b, &X);
  orthonormalize(b, &X, nullptr);
  result.vectors = std::move(X);
  return result;
}

}  // namespace unfold
