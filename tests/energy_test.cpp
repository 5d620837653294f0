// Energy terms: each term's autodiff gradient against central finite
// differences and against the analytic gradient 2 H Q - 2 B(R) that the
// local-global solver uses; the O(n) stretch term against the O(n^2) pair sum;
// the Ceres cost functions against the direct sums; the local step's rotations
// as a stationary point of the ARAP term.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <functional>

#include "energies/arap_energy.h"
#include "energies/cotangent_weights.h"
#include "energies/edge_length_energy.h"
#include "energies/stretch_energy.h"
#include "energies/user_pairs_energy.h"
#include "energies/volume_energy.h"
#include "geometry/best_rotation.h"
#include "geometry/row_major.h"
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
    Q.rowwise() -= Q.colwise().mean();  // H may omit 1 1^T terms: compare on zero-mean Q
    for (int i = 0; i < n; ++i) R.push_back(test::random_rotation(100 + unsigned(i)));
  }
  std::vector<UserPair> pairs() const {
    return {{0, n - 1, Eigen::Vector3d(1, -2, 0.5)}, {3, 7, Eigen::Vector3d(0, 0.3, 0)}};
  }
};

Eigen::MatrixX3d gradient_of(const EnergyTerm& term, const Eigen::MatrixX3d& Q,
                             const Rotations& R) {
  Eigen::MatrixX3d grad = Eigen::MatrixX3d::Zero(Q.rows(), 3);
  term.evaluate(Q, R, 1.0, &grad);
  return grad;
}

void expect_gradient_matches_finite_differences(const EnergyTerm& term, const Eigen::MatrixX3d& Q,
                                                const Rotations& R) {
  const Eigen::MatrixX3d analytic = gradient_of(term, Q, R);
  Eigen::MatrixX3d numeric(Q.rows(), 3);
  const double h = 1e-5;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      Eigen::MatrixX3d plus = Q, minus = Q;
      plus(i, k) += h;
      minus(i, k) -= h;
      numeric(i, k) =
          (term.evaluate(plus, R, 1.0, nullptr) - term.evaluate(minus, R, 1.0, nullptr)) / (2 * h);
    }
  EXPECT_LT((analytic - numeric).norm(), 1e-6 * numeric.norm())
      << term.name() << ": relative error " << (analytic - numeric).norm() / numeric.norm();
}

// For quadratic terms: e = tr(Q^T H Q) - 2 tr(Q^T B) + c, so grad = 2 H Q - 2 B.
void expect_gradient_matches_system(const EnergyTerm& term, const Eigen::MatrixX3d& Q,
                                    const Rotations& R) {
  ASSERT_TRUE(term.quadratic());
  std::vector<Eigen::Triplet<double>> triplets;
  term.add_hessian(1.0, &triplets);
  Eigen::SparseMatrix<double> H(Q.rows(), Q.rows());
  H.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::MatrixX3d B = Eigen::MatrixX3d::Zero(Q.rows(), 3);
  term.add_linear(R, 1.0, &B);
  const Eigen::MatrixX3d expected = 2 * (H * Q) - 2 * B;
  const Eigen::MatrixX3d autodiff = gradient_of(term, Q, R);
  EXPECT_LT((autodiff - expected).norm(), 1e-10 * expected.norm()) << term.name();
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
  EXPECT_NEAR(StretchEnergy(s.graph, 1.0).evaluate(s.Q, s.R, 1.0, nullptr), brute,
              1e-9 * std::abs(brute));
}

TEST(EnergyGradients, EveryTermMatchesFiniteDifferences) {
  EnergySetup s;
  expect_gradient_matches_finite_differences(StretchEnergy(s.graph, 1.0), s.Q, s.R);
  expect_gradient_matches_finite_differences(
      ArapEnergy(s.graph, s.mesh.V, std::vector<double>(size_t(s.graph.num_edges()), 1.0), 1.0),
      s.Q, s.R);
  expect_gradient_matches_finite_differences(
      ArapEnergy(s.graph, s.mesh.V, cotangent_weights(s.mesh.V, s.mesh.T, s.graph), 1.0), s.Q, s.R);
  expect_gradient_matches_finite_differences(UserPairsEnergy(s.pairs(), 1.0), s.Q, s.R);
  expect_gradient_matches_finite_differences(VolumeEnergy(s.mesh.V, s.mesh.T, 1.0), s.Q, s.R);
  expect_gradient_matches_finite_differences(EdgeLengthEnergy(s.graph, s.mesh.V, 1.0), s.Q, s.R);
}

TEST(EnergyEdgeLength, ZeroForARigidMotionAndTwiceTheEdgeSumOtherwise) {
  EnergySetup s;
  const EdgeLengthEnergy term(s.graph, s.mesh.V, 1.0);
  const Eigen::MatrixX3d moved =
      (s.mesh.V * test::random_rotation(3).transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  EXPECT_NEAR(term.evaluate(moved, s.R, 1.0, nullptr), 0, 1e-20);
  double sum = 0;
  for (int e = 0; e < s.graph.num_edges(); ++e) {
    const int i = s.graph.edges(e, 0), j = s.graph.edges(e, 1);
    const double d = (s.Q.row(i) - s.Q.row(j)).norm() - (s.mesh.V.row(i) - s.mesh.V.row(j)).norm();
    sum += 2 * d * d;
  }
  EXPECT_NEAR(term.evaluate(s.Q, s.R, 1.0, nullptr), sum, 1e-10 * sum);
}

TEST(EnergyEdgeLength, GrowsLikeTheArapTermFarFromRest) {
  // Far from rest e_l ~ tr(Q^T H Q) with H its growth Hessian (2 L), as for ARAP.
  EnergySetup s;
  const EdgeLengthEnergy term(s.graph, s.mesh.V, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  term.add_growth_hessian(1.0, &triplets);
  Eigen::SparseMatrix<double> H(s.n, s.n);
  H.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixX3d far = 1e4 * s.Q;
  const double quadratic = (far.transpose() * (H * far)).trace();
  EXPECT_NEAR(term.evaluate(far, s.R, 1.0, nullptr) / quadratic, 1.0, 1e-3);
}

TEST(EnergyGradients, QuadraticTermsMatchTheLocalGlobalSystem) {
  EnergySetup s;
  expect_gradient_matches_system(StretchEnergy(s.graph, 1.0), s.Q, s.R);
  expect_gradient_matches_system(
      ArapEnergy(s.graph, s.mesh.V, cotangent_weights(s.mesh.V, s.mesh.T, s.graph), 1.0), s.Q, s.R);
  expect_gradient_matches_system(UserPairsEnergy(s.pairs(), 1.0), s.Q, s.R);
}

TEST(EnergyArap, ZeroForARigidMotionWithItsRotation) {
  EnergySetup s;
  const ArapEnergy arap(s.graph, s.mesh.V, std::vector<double>(size_t(s.graph.num_edges()), 1.0),
                        1.0);
  const Eigen::Matrix3d R0 = test::random_rotation(9);
  const Eigen::MatrixX3d Q = (s.mesh.V * R0.transpose()).rowwise() + Eigen::RowVector3d(4, 5, 6);
  EXPECT_NEAR(arap.evaluate(Q, Rotations(size_t(s.n), R0), 1.0, nullptr), 0.0, 1e-20);
  EXPECT_GT(arap.evaluate(Q, s.R, 1.0, nullptr), 1.0);
}

TEST(EnergyArap, LocalStepRotationsAreStationary) {
  // The fitted R_i minimise the ARAP term over rotations: turning any of them
  // by a small angle t changes the energy by O(t^2), never lowering it.
  EnergySetup s;
  const ArapEnergy arap(s.graph, s.mesh.V, cotangent_weights(s.mesh.V, s.mesh.T, s.graph), 1.0);
  std::vector<Eigen::Matrix3d> S(size_t(s.n), Eigen::Matrix3d::Zero());
  arap.add_rotation_covariance(s.Q, 1.0, &S);
  Rotations R;
  for (const auto& Si : S) R.push_back(best_rotation(Si));
  const double e0 = arap.evaluate(s.Q, R, 1.0, nullptr);
  for (int i : {0, s.n / 2, s.n - 1})
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                        Eigen::Vector3d(Eigen::Vector3d(1, 1, 1).normalized())}) {
      auto turned = [&](double t) {
        Rotations Rt = R;
        Rt[size_t(i)] = R[size_t(i)] * Eigen::AngleAxisd(t, axis).toRotationMatrix();
        return arap.evaluate(s.Q, Rt, 1.0, nullptr) - e0;
      };
      const double d1 = turned(1e-3), d2 = turned(2e-3), dm = turned(-1e-3);
      EXPECT_GE(d1, -1e-12);
      EXPECT_GE(dm, -1e-12);
      EXPECT_NEAR(d2 / d1, 4.0, 0.05) << "vertex " << i;  // quadratic, no linear part
    }
}

TEST(EnergyCeres, CostFunctionsAgreeWithTheTerms) {
  // The same functors through ceres::AutoDiffCostFunction, as a ceres::Problem
  // would use them: residuals and Jacobians reproduce value and gradient.
  EnergySetup s;
  const RowMatrixX3d q = s.Q;
  auto check = [&](const EnergyTerm& term,
                   const std::vector<std::pair<ceres::CostFunction*, std::vector<int>>>& blocks,
                   double sign) {
    double energy = 0;
    Eigen::MatrixX3d grad = Eigen::MatrixX3d::Zero(s.n, 3);
    for (const auto& [cost, vertices] : blocks) {
      std::vector<const double*> params;
      for (int v : vertices) params.push_back(q.row(v).data());
      const int m = cost->num_residuals();
      std::vector<double> r(static_cast<size_t>(m));
      std::vector<std::vector<double>> J(vertices.size(), std::vector<double>(size_t(3 * m)));
      std::vector<double*> jacobians;
      for (auto& j : J) jacobians.push_back(j.data());
      cost->Evaluate(params.data(), r.data(), jacobians.data());
      for (int k = 0; k < m; ++k) energy += sign * r[size_t(k)] * r[size_t(k)];
      for (size_t b = 0; b < vertices.size(); ++b)
        for (int d = 0; d < 3; ++d)
          for (int k = 0; k < m; ++k)
            grad(vertices[b], d) += sign * 2 * r[size_t(k)] * J[b][size_t(3 * k + d)];
      delete cost;
    }
    EXPECT_NEAR(energy, term.evaluate(s.Q, s.R, 1.0, nullptr), 1e-9 * std::abs(energy))
        << term.name();
    EXPECT_LT((grad - gradient_of(term, s.Q, s.R)).norm(), 1e-9 * grad.norm()) << term.name();
  };
  const Eigen::Vector3d c = s.Q.colwise().mean().transpose();
  std::vector<std::pair<ceres::CostFunction*, std::vector<int>>> spread, edges, arap, pairs;
  for (int i = 0; i < s.n; ++i) spread.push_back({StretchSpreadResidual::Create(c, s.n), {i}});
  for (int e = 0; e < s.graph.num_edges(); ++e)
    edges.push_back({StretchEdgeResidual::Create(), {s.graph.edges(e, 0), s.graph.edges(e, 1)}});
  // The stretch term is spread (sign -1) plus edges (+1): check the parts via a difference.
  const StretchEnergy stretch(s.graph, 1.0);
  double spread_energy = 0;
  for (auto& [cost, v] : spread) {
    double r[3];
    const double* p[1] = {q.row(v[0]).data()};
    cost->Evaluate(p, r, nullptr);
    spread_energy += r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    delete cost;
  }
  double edge_energy = 0;
  for (auto& [cost, v] : edges) {
    double r[3];
    const double* p[2] = {q.row(v[0]).data(), q.row(v[1]).data()};
    cost->Evaluate(p, r, nullptr);
    edge_energy += r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    delete cost;
  }
  EXPECT_NEAR(edge_energy - spread_energy, stretch.evaluate(s.Q, s.R, 1.0, nullptr),
              1e-9 * spread_energy);

  for (int i = 0; i < s.n; ++i)
    for (int k = s.graph.offsets[size_t(i)]; k < s.graph.offsets[size_t(i) + 1]; ++k) {
      const int j = s.graph.neighbors[size_t(k)];
      arap.push_back({ArapEdgeResidual::Create(s.R[size_t(i)] *
                                               (s.mesh.V.row(i) - s.mesh.V.row(j)).transpose()),
                      {i, j}});
    }
  check(ArapEnergy(s.graph, s.mesh.V, std::vector<double>(size_t(s.graph.num_edges()), 1.0), 1.0),
        arap, 1.0);
  for (const UserPair& p : s.pairs()) pairs.push_back({UserPairResidual::Create(p.t), {p.i, p.j}});
  check(UserPairsEnergy(s.pairs(), 1.0), pairs, 1.0);
}

}  // namespace
}  // namespace unfold
