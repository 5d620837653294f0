// The function the Ceres backend hands to Ceres: min_R E(Q(z); R) over the
// preconditioned variables z, Q = P^T L^-T z. Its gradient (the fixed-R
// gradient by the envelope theorem, then the preconditioner's chain rule)
// against central finite differences in z, with every term of both backends.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/row_major.h"
#include "solvers/ceres_backend.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

void expect_objective_gradient_matches_finite_differences(const EnergyOptions& energy) {
  const test::ProblemFixture f(test::grid_tet_mesh(3, 2, 2, 0.7), energy);
  CeresBackend backend(f.problem, CeresOptions{});
  backend.set_beta(1.5 * f.n / f.lambda2);
  std::srand(11);
  RowMatrixX3d z = RowMatrixX3d::Random(f.n, 3);
  RowMatrixX3d analytic(f.n, 3), numeric(f.n, 3);
  backend.objective(z.data(), analytic.data());
  const double h = 1e-6 * z.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3 * f.n; ++k) {
    const double z_k = z.data()[k];
    z.data()[k] = z_k + h;
    const double plus = backend.objective(z.data(), nullptr);
    z.data()[k] = z_k - h;
    const double minus = backend.objective(z.data(), nullptr);
    z.data()[k] = z_k;
    numeric.data()[k] = (plus - minus) / (2 * h);
  }
  EXPECT_LT((analytic - numeric).norm(), 1e-6 * numeric.norm())
      << "relative error " << (analytic - numeric).norm() / numeric.norm();
}

TEST(CeresObjective, GradientMatchesFiniteDifferencesForThePapersEnergy) {
  expect_objective_gradient_matches_finite_differences(EnergyOptions{});
}

TEST(CeresObjective, GradientMatchesFiniteDifferencesWithEveryTerm) {
  EnergyOptions energy;
  energy.arap_weights = "cotangent";
  energy.volume_weight = 0.5;
  energy.edge_length_weight = 0.5;
  expect_objective_gradient_matches_finite_differences(energy);
}

}  // namespace
}  // namespace unfold
