// L-BFGS directions: with no pairs the initial inverse Hessian's step; the
// newest pair's secant condition holds; pairs without curvature are left out;
// with exact line searches on a quadratic the steps reach its minimum in as
// many steps as it has dimensions, as conjugate gradients do; an initial inverse
// scaled to the function's curvature along the last step gives Newton's direction
// on a quadratic.
#include "solvers/lbfgs_direction.h"

#include <gtest/gtest.h>
#include <omp.h>

#include "core/errors.h"
#include "core/parallel.h"

namespace unfold {
namespace {

// H0 = diag(1 / 2, 1 / 3, 1 / 4) on each row.
void diagonal_inverse(const Eigen::MatrixX3d& q, Eigen::MatrixX3d* r) {
  *r = q * Eigen::Vector3d(0.5, 1.0 / 3, 0.25).asDiagonal();
}

// A symmetric positive definite operator on 2 x 3 matrices (as 6-vectors).
Eigen::MatrixXd spd6() {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Random(6, 6);
  return M * M.transpose() + 0.5 * Eigen::MatrixXd::Identity(6, 6);
}

Eigen::MatrixX3d apply(const Eigen::MatrixXd& A, const Eigen::MatrixX3d& x) {
  return (A * x.reshaped()).reshaped(x.rows(), 3);
}

TEST(LbfgsDirection, WithNoPairsIsTheInitialInverseStep) {
  LbfgsDirection lbfgs(5);
  const Eigen::MatrixX3d g = Eigen::MatrixX3d::Random(4, 3);
  Eigen::MatrixX3d d, h0g;
  lbfgs.direction(g, diagonal_inverse, &d);
  diagonal_inverse(g, &h0g);
  EXPECT_LT((d + h0g).norm(), 1e-15);
  EXPECT_EQ(lbfgs.size(), 0);
}

TEST(LbfgsDirection, MapsTheNewestGradientChangeOntoItsStep) {
  // The BFGS update's secant condition H y = s, for the newest pair whatever came before.
  const Eigen::MatrixXd A = spd6();
  LbfgsDirection lbfgs(3);
  Eigen::MatrixX3d d;
  for (int k = 0; k < 5; ++k) {
    const Eigen::MatrixX3d s = Eigen::MatrixX3d::Random(2, 3);
    const Eigen::MatrixX3d y = apply(A, s);
    ASSERT_TRUE(lbfgs.update(s, y, Eigen::MatrixX3d::Zero(2, 3)));
    lbfgs.direction(y, diagonal_inverse, &d);
    EXPECT_LT((d + s).norm(), 1e-10 * s.norm()) << "pair " << k;
  }
  EXPECT_EQ(lbfgs.size(), 3);
}

TEST(LbfgsDirection, LeavesOutAPairWithoutCurvature) {
  LbfgsDirection lbfgs(3);
  const Eigen::MatrixX3d s = Eigen::MatrixX3d::Random(2, 3);
  const Eigen::MatrixX3d zero = Eigen::MatrixX3d::Zero(2, 3);
  EXPECT_FALSE(lbfgs.update(s, -s, zero));
  EXPECT_EQ(lbfgs.size(), 0);
  EXPECT_TRUE(lbfgs.update(s, s, zero));
  EXPECT_EQ(lbfgs.size(), 1);
  lbfgs.reset();
  EXPECT_EQ(lbfgs.size(), 0);
}

TEST(LbfgsDirection, MinimisesAQuadraticInAsManyExactStepsAsItHasDimensions) {
  const Eigen::MatrixXd A = spd6();
  const Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(2, 3);
  LbfgsDirection lbfgs(6);
  Eigen::MatrixX3d x = Eigen::MatrixX3d::Zero(2, 3), d;
  Eigen::MatrixX3d g = apply(A, x) - b;  // the gradient of x.A x / 2 - b.x
  const double start = g.norm();
  for (int k = 0; k < 6; ++k) {
    lbfgs.direction(g, diagonal_inverse, &d);
    const Eigen::MatrixX3d Ad = apply(A, d);
    const double t = -g.reshaped().dot(d.reshaped()) / d.reshaped().dot(Ad.reshaped());
    x += t * d;
    const Eigen::MatrixX3d g_after = apply(A, x) - b;
    lbfgs.update(t * d, g_after, g);
    g = g_after;
  }
  EXPECT_LT(g.norm(), 1e-9 * start);
}

// An initial inverse four times too stiff (H0 = A^-1 / 4), scaled by s.H0^-1 s / s.y = 4 from
// one pair on a quadratic (s.y as the pair keeps it), is A^-1: the direction is Newton's. Unscaled
// it is not; without pairs the scale is not used.
TEST(LbfgsDirection, ScaledInitialInverseGivesNewtonsDirectionOnAQuadratic) {
  const Eigen::MatrixXd A = spd6();
  const Eigen::MatrixXd stiff_inverse = A.inverse() / 4;
  const auto h0 = [&](const Eigen::MatrixX3d& q, Eigen::MatrixX3d* r) {
    *r = apply(stiff_inverse, q);
  };
  const Eigen::MatrixX3d s = Eigen::MatrixX3d::Random(2, 3), g = Eigen::MatrixX3d::Random(2, 3);
  const Eigen::MatrixX3d y = apply(A, s);
  const Eigen::MatrixX3d newton = -apply(A.inverse(), g);
  LbfgsDirection lbfgs(3);
  Eigen::MatrixX3d d;
  lbfgs.scale_initial_inverse(4);
  lbfgs.direction(g, h0, &d);
  EXPECT_LT((d + apply(stiff_inverse, g)).norm(), 1e-12 * d.norm());
  ASSERT_TRUE(lbfgs.update(s, y, Eigen::MatrixX3d::Zero(2, 3)));
  EXPECT_NEAR(lbfgs.newest_curvature(), s.reshaped().dot(y.reshaped()),
              1e-12 * s.norm() * y.norm());
  const double gamma = s.reshaped().dot(apply(4 * A, s).reshaped()) / lbfgs.newest_curvature();
  EXPECT_NEAR(gamma, 4, 1e-12);
  lbfgs.scale_initial_inverse(1);
  lbfgs.direction(g, h0, &d);
  EXPECT_GT((d - newton).norm(), 0.01 * newton.norm());
  lbfgs.scale_initial_inverse(gamma);
  lbfgs.direction(g, h0, &d);
  EXPECT_LT((d - newton).norm(), 1e-10 * newton.norm());
  lbfgs.reset();  // the scale goes with the pairs
  ASSERT_TRUE(lbfgs.update(s, y, Eigen::MatrixX3d::Zero(2, 3)));
  Eigen::MatrixX3d unscaled;
  lbfgs.direction(g, h0, &unscaled);
  EXPECT_GT((unscaled - newton).norm(), 0.01 * newton.norm());
}

// Long vectors are swept on all threads, in fixed segments: the same bits on one.
TEST(LbfgsDirection, GivesTheSameDirectionOnAnyThreadCount) {
  const int rows = 3 * kMinParallelRows;
  const auto run = [&](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    srand(7);
    LbfgsDirection lbfgs(3);
    Eigen::MatrixX3d g = Eigen::MatrixX3d::Random(rows, 3), d;
    for (int k = 0; k < 4; ++k) {
      const Eigen::MatrixX3d s = Eigen::MatrixX3d::Random(rows, 3);
      const Eigen::MatrixX3d g_after = g + 2 * s + 0.1 * Eigen::MatrixX3d::Random(rows, 3);
      lbfgs.update(s, g_after, g);
      g = g_after;
    }
    lbfgs.direction(g, diagonal_inverse, &d);
    omp_set_num_threads(before);
    return d;
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(LbfgsDirection, RefusesAnEmptyWindow) { EXPECT_THROW(LbfgsDirection(0), UsageError); }

}  // namespace
}  // namespace unfold
