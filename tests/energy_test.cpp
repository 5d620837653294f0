// Energy terms: the Ceres functors' gradients against central finite
// differences, the O(n) stretch term against the O(n^2) pair sum, and the
// Ceres cost functions against the direct evaluation.
#include <gtest/gtest.h>

#include <functional>

#include "energies/unfold_energy.h"
#include "test_meshes.h"

namespace unfold {
namespace {

struct EnergySetup {
  TetMesh mesh = test::grid_tet_mesh(3, 2, 2, 0.7);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  int n = int(mesh.V.rows());
  Eigen::MatrixX3d Q;
  Rotations R;
  EnergySetup() {
    std::srand(5);
    Q = mesh.V + 0.3 * Eigen::MatrixX3d::Random(n, 3);
    for (int i = 0; i < n; ++i) R.push_back(test::random_rotation(100 + unsigned(i)));
  }
};

Eigen::MatrixX3d finite_difference_gradient(const std::function<double(const Eigen::MatrixX3d&)>& f,
                                            const Eigen::MatrixX3d& Q) {
  Eigen::MatrixX3d grad(Q.rows(), 3);
  const double h = 1e-5;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      Eigen::MatrixX3d plus = Q, minus = Q;
      plus(i, k) += h;
      minus(i, k) -= h;
      grad(i, k) = (f(plus) - f(minus)) / (2 * h);
    }
  return grad;
}

void expect_gradient_matches(const std::function<double(const Eigen::MatrixX3d&)>& f,
                             const Eigen::MatrixX3d& analytic, const Eigen::MatrixX3d& Q) {
  const Eigen::MatrixX3d numeric = finite_difference_gradient(f, Q);
  EXPECT_LT((analytic - numeric).norm(), 1e-6 * numeric.norm())
      << "relative error " << (analytic - numeric).norm() / numeric.norm();
}

TEST(EnergyStretch, EqualsTheSumOverNonNeighbourPairs) {
  EnergySetup s;
  double brute = 0;
  for (int i = 0; i < s.n; ++i)
    for (int j = 0; j < s.n; ++j) {
      bool neighbour = false;
      for (int k = s.graph.offsets[size_t(i)]; k < s.graph.offsets[size_t(i) + 1]; ++k)
        neighbour |= s.graph.neighbors[size_t(k)] == j;
      if (!neighbour) brute -= (s.Q.row(i) - s.Q.row(j)).squaredNorm();
    }
  EXPECT_NEAR(stretch_energy(s.graph, s.Q), brute, 1e-9 * std::abs(brute));
}

TEST(EnergyStretch, GradientMatchesFiniteDifferences) {
  EnergySetup s;
  Eigen::MatrixX3d grad;
  stretch_energy(s.graph, s.Q, &grad);
  expect_gradient_matches([&](const Eigen::MatrixX3d& X) { return stretch_energy(s.graph, X); },
                          grad, s.Q);
}

TEST(EnergyArap, GradientMatchesFiniteDifferences) {
  EnergySetup s;
  Eigen::MatrixX3d grad;
  arap_energy(s.graph, s.mesh.V, s.Q, s.R, &grad);
  expect_gradient_matches(
      [&](const Eigen::MatrixX3d& X) { return arap_energy(s.graph, s.mesh.V, X, s.R); }, grad, s.Q);
}

TEST(EnergyArap, ZeroForARigidMotionWithItsRotation) {
  EnergySetup s;
  const Eigen::Matrix3d R0 = test::random_rotation(9);
  const Eigen::MatrixX3d Q = (s.mesh.V * R0.transpose()).rowwise() + Eigen::RowVector3d(4, 5, 6);
  const Rotations R(size_t(s.n), R0);
  EXPECT_NEAR(arap_energy(s.graph, s.mesh.V, Q, R), 0.0, 1e-20);
  EXPECT_GT(arap_energy(s.graph, s.mesh.V, Q, s.R), 1.0);
}

TEST(EnergyTotal, GradientMatchesFiniteDifferences) {
  EnergySetup s;
  const double beta = 7.5;
  Eigen::MatrixX3d grad;
  unfold_energy(s.graph, s.mesh.V, s.Q, s.R, beta, &grad);
  expect_gradient_matches(
      [&](const Eigen::MatrixX3d& X) { return unfold_energy(s.graph, s.mesh.V, X, s.R, beta); },
      grad, s.Q);
}

TEST(EnergyCeres, CostFunctionsAgreeWithTheDirectSums) {
  // The same functors through ceres::AutoDiffCostFunction (as a Ceres solver
  // would use them): residuals and Jacobians reproduce energy and gradient.
  EnergySetup s;
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> q = s.Q;
  const Eigen::Vector3d c = s.Q.colwise().mean().transpose();
  double energy = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> grad = Eigen::MatrixX3d::Zero(s.n, 3);
  auto accumulate = [&](ceres::CostFunction* cost, std::vector<int> vertices, double sign) {
    std::vector<const double*> params;
    for (int v : vertices) params.push_back(q.row(v).data());
    double r[3], J[2][9];
    double* jacobians[2] = {J[0], J[1]};
    cost->Evaluate(params.data(), r, jacobians);
    energy += sign * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (size_t b = 0; b < vertices.size(); ++b)
      for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 3; ++k) grad(vertices[b], d) += sign * 2 * r[k] * J[b][3 * k + d];
    delete cost;
  };
  for (int i = 0; i < s.n; ++i) accumulate(StretchSpreadResidual::Create(c, s.n), {i}, -1);
  for (int e = 0; e < s.graph.num_edges(); ++e)
    accumulate(StretchEdgeResidual::Create(), {s.graph.edges(e, 0), s.graph.edges(e, 1)}, 1);
  Eigen::MatrixX3d expected_grad;
  const double expected = stretch_energy(s.graph, s.Q, &expected_grad);
  EXPECT_NEAR(energy, expected, 1e-9 * std::abs(expected));
  EXPECT_LT((Eigen::MatrixX3d(grad) - expected_grad).norm(), 1e-9 * expected_grad.norm());
}

}  // namespace
}  // namespace unfold
