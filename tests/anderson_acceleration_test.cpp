// Anderson acceleration: it finds the fixed point of a slow linear iteration
// in a few steps, and inside the local-global cascade it lowers the energy
// faster than plain iterations while never letting it rise.
#include "solvers/anderson_acceleration.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <deque>
#include <vector>

#include "solvers/cascade.h"
#include "solvers/local_global.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

TEST(AndersonAcceleration, SolvesASlowLinearIterationInAFewSteps) {
  // x <- M x + b contracts by 0.99 along one direction: plain iteration needs
  // about 2,000 steps for 1e-9; with a window covering the dimension, the
  // residual fit recovers the fixed point exactly once the window is full.
  const int n = 4;
  const Eigen::Vector4d contraction(0.99, 0.9, 0.5, 0.1);
  const Eigen::Vector4d b(1, -2, 3, 0.5);
  const auto G = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return contraction.cwiseProduct(x) + b;
  };
  const Eigen::VectorXd fixed = b.cwiseQuotient(Eigen::Vector4d::Ones() - contraction);
  AndersonAcceleration anderson(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), plain = x;
  for (int k = 0; k < n + 2; ++k) {
    anderson.next(x, G(x), x);
    plain = G(plain);
  }
  EXPECT_LT((x - fixed).norm(), 1e-9 * fixed.norm());
  EXPECT_GT((plain - fixed).norm(), 0.5 * fixed.norm());
  anderson.reset();  // after a reset the first step is the plain one
  Eigen::VectorXd first(n);
  anderson.next(plain, G(plain), first);
  EXPECT_EQ(first, G(plain));
}

// The window slides: once it is full each step drops the oldest difference.
// Every step equals the fit written out afresh (the last `window` differences,
// a least-squares fit by a QR of them), across the slide and a reset.
TEST(AndersonAcceleration, EachStepIsTheFitOfTheLastWindowOfDifferences) {
  const int n = 7, window = 3;
  const auto G = [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return (0.8 * x.array().sin() + 0.3).matrix();
  };
  AndersonAcceleration anderson(window);
  std::deque<Eigen::VectorXd> dF, dG;
  Eigen::VectorXd last_f, last_g;
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -1, 2);
  for (int k = 0; k < 10; ++k) {
    if (k == 6) {  // a reset forgets the differences
      anderson.reset();
      dF.clear();
      dG.clear();
      last_f.resize(0);
    }
    const Eigen::VectorXd g = G(x), f = g - x;
    if (last_f.size() == n) {
      dF.push_back(f - last_f);
      dG.push_back(g - last_g);
      if (int(dF.size()) > window) dF.pop_front(), dG.pop_front();
    }
    last_f = f;
    last_g = g;
    Eigen::VectorXd expected = g;
    if (!dF.empty()) {
      Eigen::MatrixXd F(n, Eigen::Index(dF.size())), D(n, F.cols());
      for (Eigen::Index c = 0; c < F.cols(); ++c)
        F.col(c) = dF[size_t(c)], D.col(c) = dG[size_t(c)];
      expected = g - D * F.colPivHouseholderQr().solve(f);
    }
    Eigen::VectorXd next(n);
    anderson.next(x, g, next);
    ASSERT_LT((next - expected).norm(), 1e-9 * expected.norm()) << "step " << k;
    if (k == 0 || k == 6) {
      EXPECT_EQ(next, g) << "step " << k;  // no differences yet
    }
    x = next;
  }
}

// Steps that repeat a direction give a window of parallel differences (a
// singular fit): the step stays finite, and on a map that only contracts
// toward its fixed point it lands there at once. A map that moves by the same
// amount every time gives zero differences: the plain step, never a NaN.
TEST(AndersonAcceleration, ParallelAndZeroDifferencesDoNoHarm) {
  const int n = 5;
  const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(n, 1, 3);
  const auto contract = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return a + 0.5 * (x - a);
  };
  AndersonAcceleration anderson(4);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 6; ++k) {
    anderson.next(x, contract(x), x);
    ASSERT_TRUE(x.allFinite()) << "step " << k;
    if (k >= 1) {
      EXPECT_LT((x - a).norm(), 1e-12 * a.norm()) << "step " << k;
    }
  }
  const Eigen::VectorXd shift = Eigen::VectorXd::Constant(n, 0.25);
  AndersonAcceleration drift(3);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 5; ++k) {
    const Eigen::VectorXd g = y + shift;
    drift.next(y, g, y);
    ASSERT_EQ(y, g) << "step " << k;
  }
}

// Steps on vectors long enough to be swept on all threads (the positions of
// 40k vertices, the last segment short): every entry the same to the last bit
// on one thread as on two, through a window that fills and slides.
TEST(AndersonAcceleration, StepsAreTheSameOnOneThreadAsOnTwo) {
  const Eigen::Index n = 3 * 40000 + 7;
  const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(n, -1, 2).array().sin();
  const auto image = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return a + 0.9 * x.array().cos().matrix() - 0.3 * x;
  };
  const auto run = [&](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    AndersonAcceleration anderson(3);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n), out(n);
    std::vector<Eigen::VectorXd> iterates;
    for (int k = 0; k < 7; ++k) {
      anderson.next(x, image(x), out);
      x = out;
      iterates.push_back(x);
    }
    omp_set_num_threads(before);
    return iterates;
  };
  const std::vector<Eigen::VectorXd> one = run(1), two = run(2);
  for (size_t k = 0; k < one.size(); ++k) {
    EXPECT_TRUE((one[k].array() == two[k].array()).all()) << "step " << k;
  }
  EXPECT_GT((one.back() - one.front()).norm(), 0);
}

// A bar bent into a half circle: unfolding must straighten it, the slow,
// low-frequency motion that plain local-global iterations crawl through.
struct BentBar : test::ProblemFixture {
  static TetMesh bent() {
    TetMesh mesh = test::grid_tet_mesh(24, 1, 1, 0.5);
    const double length = mesh.V.col(0).maxCoeff();
    for (Eigen::Index i = 0; i < mesh.V.rows(); ++i) {
      const double angle = M_PI * mesh.V(i, 0) / length, radius = length / M_PI + mesh.V(i, 1);
      mesh.V(i, 0) = radius * std::sin(angle);
      mesh.V(i, 1) = radius * std::cos(angle);
    }
    return mesh;
  }
  BentBar() : ProblemFixture(bent()) {}
};

CascadeResult one_cascade(const BentBar& f, int anderson, int iterations) {
  CascadeOptions options;
  options.beta = 4 * f.n / f.lambda2;
  options.num_cascades = 1;
  options.epsilon = 0;                 // no convergence stop
  options.edge_ratio_band = {-1, -1};  // nor a band stop
  options.anderson = anderson;
  options.k_iter = iterations;
  LocalGlobalBackend backend(f.problem);
  return run_cascade(f.problem, backend, options);
}

TEST(AndersonAcceleration, LowersTheLocalGlobalEnergyFasterAndMonotonically) {
  const BentBar f;
  const CascadeResult plain = one_cascade(f, 0, 15), accelerated = one_cascade(f, 5, 15);
  const CascadeResult converged = one_cascade(f, 0, 3000);
  // How much of the way to the minimum 15 iterations go.
  const auto left = [&](const CascadeResult& r) {
    return (r.final_energy - converged.final_energy) /
           (plain.history.front().energy - converged.final_energy);
  };
  EXPECT_LT(left(accelerated), 0.5 * left(plain));
  for (size_t k = 1; k < accelerated.history.size(); ++k)
    EXPECT_LE(accelerated.history[k].energy, accelerated.history[k - 1].energy)
        << "iteration " << k + 1;
}

}  // namespace
}  // namespace unfold
