#include "geometry/best_rotation.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

namespace unfold {
namespace {

// Cofactor matrix C of A (A^{-T} = C / det A), and det A, without pivoting:
// callers only pass well-conditioned matrices.
inline double cofactor(const Eigen::Matrix3d& A, Eigen::Matrix3d* C) {
  C->col(0) = A.col(1).cross(A.col(2));
  C->col(1) = A.col(2).cross(A.col(0));
  C->col(2) = A.col(0).cross(A.col(1));
  return A.col(0).dot(C->col(0));
}

// Kabsch through the SVD: the reference method, and the fallback for cells
// whose covariance is (near) singular or orientation-reversing.
Eigen::Matrix3d rotation_by_svd(const Eigen::Matrix3d& cov) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d V = svd.matrixV();
  Eigen::Matrix3d R = V * U.transpose();
  if (R.determinant() < 0) {
    U.col(2) = -U.col(2);  // singular values are sorted: column 2 is the weakest
    R = V * U.transpose();
  }
  return R;
}

}  // namespace

Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov) {
  // With cov = U S V^T the answer is V U^T, the orthogonal polar factor of
  // cov^T whenever det(cov) > 0. Higham's scaled Newton iteration
  // X <- (z X + X^{-T} / z) / 2 reaches it in ~6-8 steps of 3x3 cofactors,
  // far cheaper than a Jacobi SVD. It needs det(X) clearly positive (no
  // reflection to fix, no rank loss): checked through the scale-free
  // ratio det(cov) / |cov|_F^3, which is 3^{-3/2} for a multiple of a rotation and
  // goes to 0 with the smallest singular value.
  const double norm = cov.norm();
  if (!(norm > 0)) return rotation_by_svd(cov);
  Eigen::Matrix3d X = cov.transpose() / norm;  // unit scale: no over/underflow below
  Eigen::Matrix3d C;
  double det = cofactor(X, &C);
  if (!(det > 1e-6)) return rotation_by_svd(cov);
  for (int k = 0; k < 30; ++k) {
    // Frobenius scaling z = (|X^{-1}|_F / |X|_F)^{1/2}, X^{-1} = C^T / det.
    const double z = std::sqrt(C.norm() / (det * X.norm()));
    const Eigen::Matrix3d next = 0.5 * (z * X + C / (z * det));
    const double change = (next - X).squaredNorm();
    X = next;
    if (change < 1e-26) return X;  // quadratic convergence: X is exact to roundoff
    det = cofactor(X, &C);
  }
  return rotation_by_svd(cov);  // not reached for the conditioning admitted above
}

Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov, const Eigen::Matrix3d& guess) {
  Eigen::Matrix3d R = guess;
  const Eigen::Matrix3d* c = &cov;
  Eigen::Matrix3d* r = &R;
  best_rotations_from_guesses(&c, &r, 1);
  return R;
}

// R maximises tr(R^T M) with M = cov^T: Y = R^T M is symmetric there, and
// since tr(Y exp([w]x)) = tr(Y) + 2 a.w - w^T G w / 2 + ..., G = tr(S) I - S,
// the maximum is the critical point where G is positive definite (at every
// other one Y has two negative eigenvalues, or one not on the weakest
// direction, and G is not). Writing R <- R exp([w]x) and linearising the
// symmetry of exp(-[w]x) Y gives G w = 2 a, with S and [a]x the symmetric
// and skew parts of Y. The update is applied by the Cayley map, which agrees
// with exp to first order (enough for Newton) and is exactly orthogonal.
//
// Written out on scalars, a packet of cells side by side: each step's loop
// over the lanes is branch-free (a lane that is done or failed is computed
// and not kept), so GCC vectorizes it, two lanes per SSE2 instruction and four
// in the AVX2 clone (no FMA: a lane's operations, and so its rounding, are
// one cell's alone). The sums are in the order Eigen's 3x3 products took
// when this was written with them (R^T M: left to right; R U: left to right
// in rows 0 and 1, right to left in row 2), so the rotations are bit for bit
// those of before (docs/history/performance.md).
__attribute__((target_clones("avx2", "default"))) void best_rotations_from_guesses(
    const Eigen::Matrix3d* const* cov, Eigen::Matrix3d* const* rotation, int count) {
  constexpr int L = kRotationPacket;
  // m[3 i + j] = M(i, j) = cov(j, i), r[3 i + j] = R(i, j); lanes past count
  // are the identity with M = I, done at once.
  alignas(64) double m[9][L], r[9][L], next[9][L];
  alignas(64) double det[L], step[L], g00[L], c22[L];
  enum : char { kRunning, kDone, kFailed };
  char state[L];
  for (int l = 0; l < L; ++l)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        m[3 * i + j][l] = l < count ? (*cov[l])(j, i) : double(i == j);
        r[3 * i + j][l] = l < count ? (*rotation[l])(i, j) : double(i == j);
      }
  for (int l = 0; l < L; ++l) state[l] = l < count ? kRunning : kDone;
  for (int k = 0; k < 4; ++k) {
    for (int l = 0; l < L; ++l) {
      // Y = R^T M.
      double y[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          y[i][j] = (r[i][l] * m[j][l] + r[3 + i][l] * m[3 + j][l]) + r[6 + i][l] * m[6 + j][l];
      const double s00 = y[0][0], s11 = y[1][1], s22 = y[2][2];
      const double s01 = 0.5 * (y[0][1] + y[1][0]), s02 = 0.5 * (y[0][2] + y[2][0]),
                   s12 = 0.5 * (y[1][2] + y[2][1]);
      // Half the Newton step, c = w / 2, solves G c = a with G = tr(S) I - S
      // (symmetric), by cofactors.
      const double a0 = 0.5 * (y[2][1] - y[1][2]), a1 = 0.5 * (y[0][2] - y[2][0]),
                   a2 = 0.5 * (y[1][0] - y[0][1]);
      const double h00 = s11 + s22, h11 = s00 + s22, h22 = s00 + s11;
      const double c00 = h11 * h22 - s12 * s12, c01 = s01 * h22 + s02 * s12,
                   c02 = s01 * s12 + s02 * h11, c11 = h00 * h22 - s02 * s02,
                   c12 = h00 * s12 + s01 * s02;
      c22[l] = h00 * h11 - s01 * s01;
      g00[l] = h00;
      det[l] = h00 * c00 - s01 * c01 - s02 * c02;
      const double c0 = (c00 * a0 + c01 * a1 + c02 * a2) / det[l],
                   c1 = (c01 * a0 + c11 * a1 + c12 * a2) / det[l],
                   c2 = (c02 * a0 + c12 * a1 + c22[l] * a2) / det[l];
      step[l] = c0 * c0 + c1 * c1 + c2 * c2;
      // Cayley: U = I + 2 / (1 + |c|^2) ([c]x + [c]x^2), [c]x^2 = c c^T - |c|^2 I.
      const double f = 2 / (1 + step[l]), d = 1 - f * step[l];
      const double u[3][3] = {{d + f * c0 * c0, f * (c0 * c1 - c2), f * (c0 * c2 + c1)},
                              {f * (c1 * c0 + c2), d + f * c1 * c1, f * (c1 * c2 - c0)},
                              {f * (c2 * c0 - c1), f * (c2 * c1 + c0), d + f * c2 * c2}};
      // R U.
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j)
          next[3 * i + j][l] =
              (r[3 * i][l] * u[0][j] + r[3 * i + 1][l] * u[1][j]) + r[3 * i + 2][l] * u[2][j];
      for (int j = 0; j < 3; ++j)
        next[6 + j][l] = r[6][l] * u[0][j] + (r[7][l] * u[1][j] + r[8][l] * u[2][j]);
    }
    bool running = false;
    for (int l = 0; l < L; ++l) {
      if (state[l] != kRunning) continue;
      // G is positive definite when S is: far from the answer; a step of
      // |w| >= 1/2: not close enough for Newton.
      if (!(det[l] > 0) || !(step[l] < 0.0625)) {
        state[l] = kFailed;
        continue;
      }
      for (int e = 0; e < 9; ++e) r[e][l] = next[e][l];
      // |w| < 1e-6: R is now exact to ~|w|^2. It is the maximiser, not another
      // critical point, iff G is positive definite (Sylvester's criterion: its
      // determinant is positive already). S need not be: a flat cell's S is
      // singular, and a reflected one's has its weakest direction negative.
      if (step[l] < 2.5e-13) state[l] = g00[l] > 0 && c22[l] > 0 ? kDone : kFailed;
      running = running || state[l] == kRunning;
    }
    if (!running) break;
  }
  for (int l = 0; l < count; ++l) {
    if (state[l] != kDone) {
      *rotation[l] = best_rotation(*cov[l]);
      continue;
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) (*rotation[l])(i, j) = r[3 * i + j][l];
  }
}

}  // namespace unfold
