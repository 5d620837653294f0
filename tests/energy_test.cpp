// Energy terms, one parameterised case per term (a failing term names itself):
// every term's autodiff gradient against central finite differences; every
// quadratic term's derived form (H, B, c) against its values and gradients,
// and the hand-written fast paths (ARAP) against the derived forms; the O(n)
// stretch term against the O(n^2) pair sum; the local step's rotations as a
// stationary point of the ARAP term.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <functional>
#include <memory>

#include "core/errors.h"
#include "energies/arap_energy.h"
#include "energies/cotangent_weights.h"
#include "energies/distance_clusters.h"
#include "energies/distance_spread_energy.h"
#include "energies/edge_length_energy.h"
#include "energies/residual_sum.h"
#include "energies/stretch_energy.h"
#include "energies/user_pairs_energy.h"
#include "energies/volume_energy.h"
#include "geometry/best_rotation.h"
#include "mesh/lumped_masses.h"
#include "test_meshes.h"

namespace unfold {
namespace {

struct EnergySetup {
  TetMesh mesh = test::grid_tet_mesh(3, 2, 2, 0.7);
  std::shared_ptr<const EdgeGraph> graph =
      std::make_shared<const EdgeGraph>(build_edge_graph(int(mesh.V.rows()), mesh.T));
  int n = int(mesh.V.rows());
  Eigen::MatrixX3d Q;
  Rotations R;
  EnergySetup() {
    std::srand(5);
    Q = mesh.V + 0.3 * Eigen::MatrixX3d::Random(n, 3);
    Q.rowwise() -= Q.colwise().mean();  // H may omit 1 1^T terms: compare on zero-mean Q
    for (int i = 0; i < n; ++i) R.push_back(test::random_rotation(100 + unsigned(i)));
  }
  std::vector<double> uniform() const { return std::vector<double>(size_t(graph->num_edges()), 1); }
  std::vector<double> cotangent() const { return cotangent_weights(mesh.V, mesh.T, *graph); }
  std::vector<UserPair> pairs() const {
    return {{0, n - 1, Eigen::Vector3d(1, -2, 0.5)}, {3, 7, Eigen::Vector3d(0, 0.3, 0)}};
  }
};

struct TermCase {
  std::string name;
  std::function<std::unique_ptr<EnergyTerm>(const EnergySetup&)> make;
};

void PrintTo(const TermCase& c, std::ostream* os) { *os << c.name; }

std::string case_name(const ::testing::TestParamInfo<TermCase>& info) { return info.param.name; }

const std::vector<TermCase>& quadratic_cases() {
  static const std::vector<TermCase> cases = {
      {"stretch",
       [](const EnergySetup& s) { return std::make_unique<StretchEnergy>(s.graph, 1.0); }},
      {"stretch_lumped",
       [](const EnergySetup& s) {
         return std::make_unique<StretchEnergy>(s.graph, 1.0, lumped_masses(s.mesh.V, s.mesh.T));
       }},
      {"stretch_local",
       [](const EnergySetup& s) {
         return std::make_unique<StretchEnergy>(s.graph, 1.0, lumped_masses(s.mesh.V, s.mesh.T),
                                                spread_regions(s.mesh.V, *s.graph, {0.6, 0.4, 4}));
       }},
      {"arap_uniform",
       [](const EnergySetup& s) {
         return std::make_unique<ArapEnergy>(s.graph, s.mesh.V, s.uniform(), 1.0);
       }},
      {"arap_cotangent",
       [](const EnergySetup& s) {
         return std::make_unique<ArapEnergy>(s.graph, s.mesh.V, s.cotangent(), 1.0);
       }},
      {"user_pairs",
       [](const EnergySetup& s) { return std::make_unique<UserPairsEnergy>(s.pairs(), s.n, 1.0); }},
  };
  return cases;
}

std::vector<TermCase> all_cases() {
  std::vector<TermCase> cases = quadratic_cases();
  cases.push_back({"volume", [](const EnergySetup& s) {
                     return std::make_unique<VolumeEnergy>(s.mesh.V, s.mesh.T, 1.0);
                   }});
  cases.push_back({"edge_length", [](const EnergySetup& s) {
                     return std::make_unique<EdgeLengthEnergy>(s.graph, s.mesh.V, 1.0);
                   }});
  cases.push_back({"stretch_distance", [](const EnergySetup& s) {
                     int cells = 0;
                     std::vector<int> cell = distance_clusters(s.mesh.V, *s.graph, 5, &cells);
                     return std::make_unique<DistanceSpreadEnergy>(
                         std::move(cell), cells, lumped_masses(s.mesh.V, s.mesh.T), 1.0);
                   }});
  return cases;
}

Eigen::MatrixX3d gradient_of(const EnergyTerm& term, const Eigen::MatrixX3d& Q,
                             const Rotations& R) {
  Eigen::MatrixX3d grad = Eigen::MatrixX3d::Zero(Q.rows(), 3);
  term.evaluate(Q, R, 1.0, &grad);
  return grad;
}

class EveryTerm : public ::testing::TestWithParam<TermCase> {};

TEST_P(EveryTerm, GradientMatchesFiniteDifferences) {
  const EnergySetup s;
  const std::unique_ptr<EnergyTerm> term = GetParam().make(s);
  const Eigen::MatrixX3d analytic = gradient_of(*term, s.Q, s.R);
  Eigen::MatrixX3d numeric(s.n, 3);
  const double h = 1e-5;
  for (int i = 0; i < s.n; ++i)
    for (int k = 0; k < 3; ++k) {
      Eigen::MatrixX3d plus = s.Q, minus = s.Q;
      plus(i, k) += h;
      minus(i, k) -= h;
      numeric(i, k) =
          (term->evaluate(plus, s.R, 1.0, nullptr) - term->evaluate(minus, s.R, 1.0, nullptr)) /
          (2 * h);
    }
  EXPECT_LT((analytic - numeric).norm(), 1e-6 * numeric.norm())
      << "relative error " << (analytic - numeric).norm() / numeric.norm();
}

TEST_P(EveryTerm, ScaleMultipliesValueAndGradientAlike) {
  const EnergySetup s;
  const std::unique_ptr<EnergyTerm> term = GetParam().make(s);
  Eigen::MatrixX3d grad = Eigen::MatrixX3d::Zero(s.n, 3);
  const double value = term->evaluate(s.Q, s.R, 1.0, nullptr);
  EXPECT_NEAR(term->evaluate(s.Q, s.R, 2.5, &grad), 2.5 * value, 1e-12 * std::abs(value));
  EXPECT_LT((grad - 2.5 * gradient_of(*term, s.Q, s.R)).norm(), 1e-12 * grad.norm());
}

INSTANTIATE_TEST_SUITE_P(Energy, EveryTerm, ::testing::ValuesIn(all_cases()), case_name);

class QuadraticTermCase : public ::testing::TestWithParam<TermCase> {
 protected:
  const EnergySetup s;
  std::unique_ptr<EnergyTerm> owned = GetParam().make(s);
  const QuadraticTerm& term = dynamic_cast<const QuadraticTerm&>(*owned);

  Eigen::SparseMatrix<double> H() const {
    std::vector<Eigen::Triplet<double>> triplets;
    term.add_hessian(1.0, &triplets);
    Eigen::SparseMatrix<double> H(s.n, s.n);
    H.setFromTriplets(triplets.begin(), triplets.end());
    return H;
  }
  Eigen::MatrixX3d B(const Rotations& R) const {
    Eigen::MatrixX3d B = Eigen::MatrixX3d::Zero(s.n, 3);
    term.add_linear(R, 1.0, &B);
    return B;
  }
  // The true Hessian's product: H plus the term's rank-one and region parts.
  Eigen::MatrixX3d true_H_times(const Eigen::MatrixX3d& Q) const {
    Eigen::MatrixX3d HQ = H() * Q;
    const Eigen::VectorXd u = term.rank_one_hessian();
    if (u.size()) HQ += u * (u.transpose() * Q);
    const Eigen::MatrixXd U = term.region_hessian();
    if (U.cols()) HQ += U * (U.transpose() * Q);
    return HQ;
  }
};

// e = tr(Q^T H Q) - 2 tr(Q^T B) + c, so grad = 2 H Q - 2 B.
TEST_P(QuadraticTermCase, GradientIsTheLinearSystems) {
  const Eigen::MatrixX3d expected = 2 * true_H_times(s.Q) - 2 * B(s.R);
  EXPECT_LT((gradient_of(term, s.Q, s.R) - expected).norm(), 1e-10 * expected.norm());
}

TEST_P(QuadraticTermCase, ValueIsTheQuadraticFormWithItsConstant) {
  const double form = (s.Q.transpose() * true_H_times(s.Q)).trace() -
                      2 * (s.Q.array() * B(s.R).array()).sum() + term.constant(s.R);
  const double value = term.evaluate(s.Q, s.R, 1.0, nullptr);
  EXPECT_NEAR(form, value, 1e-10 * std::abs(value));
  EXPECT_NEAR(term.constant(s.R), term.evaluate(Eigen::MatrixX3d::Zero(s.n, 3), s.R, 1.0, nullptr),
              1e-12 * std::max(1.0, std::abs(term.constant(s.R))));
}

TEST_P(QuadraticTermCase, FastPathsEqualTheDerivedForms) {
  std::vector<Eigen::Triplet<double>> triplets;
  term.add_derived_hessian(1.0, &triplets);
  Eigen::SparseMatrix<double> derived(s.n, s.n);
  derived.setFromTriplets(triplets.begin(), triplets.end());
  EXPECT_LT((H() - derived).norm(), 1e-12 * derived.norm());
  Eigen::MatrixX3d derived_B = Eigen::MatrixX3d::Zero(s.n, 3);
  term.add_derived_linear(s.R, 1.0, &derived_B);
  EXPECT_LT((B(s.R) - derived_B).norm(), 1e-12 * std::max(1.0, derived_B.norm()));
  EXPECT_NEAR(term.constant(s.R), term.derived_constant(s.R),
              1e-12 * std::max(1.0, std::abs(term.derived_constant(s.R))));
}

INSTANTIATE_TEST_SUITE_P(Energy, QuadraticTermCase, ::testing::ValuesIn(quadratic_cases()),
                         case_name);

// A residual that treats x differently from y and z: no n x n quadratic form.
struct SquashedDifference {
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    r[0] = T(2.0) * (qi[0] - qj[0]);
    r[1] = qi[1] - qj[1];
    r[2] = qi[2] - qj[2];
    return true;
  }
};

class SquashedTerm : public QuadraticTerm {
 public:
  SquashedTerm() : QuadraticTerm(2, 1.0, true) {}
  std::string name() const override { return "squashed"; }
  double add_residuals(const Eigen::MatrixX3d&, const Rotations&, ResidualSum* sum) const override {
    return sum->add<3, 2>(SquashedDifference(), {0, 1});
  }
};

TEST(EnergyQuadraticForm, AnAnisotropicResidualIsRefusedByName) {
  std::vector<Eigen::Triplet<double>> triplets;
  try {
    SquashedTerm().add_derived_hessian(1.0, &triplets);
    FAIL() << "an anisotropic residual gave a quadratic form";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("squashed"), std::string::npos) << e.what();
  }
}

TEST(EnergyStretch, EqualsTheSumOverNonNeighbourPairs) {
  const EnergySetup s;
  const EdgeGraph& g = *s.graph;
  double brute = 0;
  for (int i = 0; i < s.n; ++i)
    for (int j = 0; j < s.n; ++j) {
      bool neighbour = false;
      for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k)
        neighbour |= g.neighbors[size_t(k)] == j;
      if (!neighbour) brute -= (s.Q.row(i) - s.Q.row(j)).squaredNorm();
    }
  EXPECT_NEAR(StretchEnergy(s.graph, 1.0).evaluate(s.Q, s.R, 1.0, nullptr), brute,
              1e-9 * std::abs(brute));
}

TEST(EnergyEdgeLength, ZeroForARigidMotionAndTwiceTheEdgeSumOtherwise) {
  const EnergySetup s;
  const EdgeLengthEnergy term(s.graph, s.mesh.V, 1.0);
  const Eigen::MatrixX3d moved =
      (s.mesh.V * test::random_rotation(3).transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  EXPECT_NEAR(term.evaluate(moved, s.R, 1.0, nullptr), 0, 1e-20);
  double sum = 0;
  for (int e = 0; e < s.graph->num_edges(); ++e) {
    const int i = s.graph->edges(e, 0), j = s.graph->edges(e, 1);
    const double d = (s.Q.row(i) - s.Q.row(j)).norm() - (s.mesh.V.row(i) - s.mesh.V.row(j)).norm();
    sum += 2 * d * d;
  }
  EXPECT_NEAR(term.evaluate(s.Q, s.R, 1.0, nullptr), sum, 1e-10 * sum);
}

TEST(EnergyEdgeLength, GrowsLikeTheArapTermFarFromRest) {
  // Far from rest e_l ~ tr(Q^T H Q) with H its growth Hessian (2 L), as for ARAP.
  const EnergySetup s;
  const EdgeLengthEnergy term(s.graph, s.mesh.V, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  term.add_growth_hessian(1.0, &triplets);
  Eigen::SparseMatrix<double> H(s.n, s.n);
  H.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixX3d far = 1e4 * s.Q;
  const double quadratic = (far.transpose() * (H * far)).trace();
  EXPECT_NEAR(term.evaluate(far, s.R, 1.0, nullptr) / quadratic, 1.0, 1e-3);
}

// A sliver at rest (the robust route's carved Delaunay mesh has them down to
// 1e-16 l^3) is measured against kMinRestVolume l^3: its term stays of the
// order of the others' instead of (l dV / V0)^2. A regular tet keeps
// l^2 (V / V0 - 1)^2.
TEST(EnergyVolume, ASliverIsMeasuredAgainstTheFloorARegularTetAgainstItself) {
  Eigen::MatrixX3d P(8, 3);
  // a regular tet (edge 2 sqrt 2), then a sliver: four nearly coplanar points
  P << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1,  //
      0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1e-12;
  Eigen::MatrixX4i T(2, 4);
  T << 0, 1, 2, 3, 4, 5, 6, 7;
  const VolumeEnergy term(P, T, 1.0);
  const Rotations R(8, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(term.evaluate(P, R, 1.0, nullptr), 0.0, 1e-20);
  const auto volume = [](const Eigen::MatrixX3d& X, int a) {
    return (X.row(a + 1) - X.row(a)).dot((X.row(a + 2) - X.row(a)).cross(X.row(a + 3) - X.row(a))) /
           6.0;
  };
  const auto l = [&](int a) {
    double sum = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) sum += (P.row(a + i) - P.row(a + j)).squaredNorm();
    return std::sqrt(sum / 6.0);
  };
  Eigen::MatrixX3d Q = P;
  Q(0, 2) += 0.1;  // the regular tet's volume changes
  const double v0 = volume(P, 0), l0 = l(0);
  EXPECT_NEAR(term.evaluate(Q, R, 1.0, nullptr), std::pow(l0 * (volume(Q, 0) / v0 - 1), 2), 1e-12);
  Q = P;
  Q(7, 2) += 0.01;  // the sliver is lifted
  const double l4 = l(4), floor = kMinRestVolume * std::pow(l4, 3);
  const double expected = std::pow(l4 * (volume(Q, 4) - volume(P, 4)) / floor, 2);
  EXPECT_NEAR(term.evaluate(Q, R, 1.0, nullptr), expected, 1e-9 * expected);
  // against its own volume it would be ~1e20 times larger
  EXPECT_LT(expected, 1e3);
}

TEST(EnergyArap, ZeroForARigidMotionWithItsRotation) {
  const EnergySetup s;
  const ArapEnergy arap(s.graph, s.mesh.V, s.uniform(), 1.0);
  const Eigen::Matrix3d R0 = test::random_rotation(9);
  const Eigen::MatrixX3d Q = (s.mesh.V * R0.transpose()).rowwise() + Eigen::RowVector3d(4, 5, 6);
  EXPECT_NEAR(arap.evaluate(Q, Rotations(size_t(s.n), R0), 1.0, nullptr), 0.0, 1e-20);
  EXPECT_GT(arap.evaluate(Q, s.R, 1.0, nullptr), 1.0);
}

TEST(EnergyArap, LocalStepRotationsAreStationary) {
  // The fitted R_i minimise the ARAP term over rotations: turning any of them
  // by a small angle t changes the energy by O(t^2), never lowering it.
  const EnergySetup s;
  const ArapEnergy arap(s.graph, s.mesh.V, s.cotangent(), 1.0);
  std::vector<Eigen::Matrix3d> S(size_t(s.n), Eigen::Matrix3d::Zero());
  static_cast<const RotationTerm&>(arap).add_rotation_covariance(s.Q, 1.0, &S);
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

}  // namespace
}  // namespace unfold
