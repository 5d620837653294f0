// Anderson acceleration: it finds the fixed point of a slow linear iteration
// in a few steps, and inside the local-global cascade it lowers the energy
// faster than plain iterations while never letting it rise.
#include "solvers/anderson_acceleration.h"

#include <gtest/gtest.h>

#include <cmath>

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
    x = anderson.next(x, G(x));
    plain = G(plain);
  }
  EXPECT_LT((x - fixed).norm(), 1e-9 * fixed.norm());
  EXPECT_GT((plain - fixed).norm(), 0.5 * fixed.norm());
  anderson.reset();  // after a reset the first step is the plain one
  EXPECT_EQ(anderson.next(plain, G(plain)), G(plain));
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
