// Adding an energy term (docs/method.md, "Adding a term"): this file is all of
// it. A new quadratic term is defined here by its residual functor alone,
// registered in a problem, and minimised by both backends, which agree on the
// final energy at a fixed beta. Neither backend knows the term: the global
// step's H, B and c come from the functor's Jacobian (energies/quadratic_term.h),
// values and gradients from its automatic differentiation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "energies/quadratic_term.h"
#include "energies/residual_sum.h"
#include "solvers/fiedler_value.h"
#include "solvers/make_backend.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

/// q_m - (q_a + q_b) / 2 - t: vertex m held at offset t from the midpoint of
/// vertices a and b. Affine in Q, and translation invariant, as every term
/// must be (the solvers work on zero-mean positions): an anchor to absolute
/// points would not be.
struct MidpointAnchorResidual {
  explicit MidpointAnchorResidual(const Eigen::Vector3d& offset) : t(offset) {}
  template <typename T>
  bool operator()(const T* qm, const T* qa, const T* qb, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = qm[k] - T(0.5) * (qa[k] + qb[k]) - T(t[k]);
    return true;
  }
  Eigen::Vector3d t;
};

struct MidpointAnchor {
  int m, a, b;
  Eigen::Vector3d offset;
};

/// e(Q) = sum over anchors |q_m - (q_a + q_b) / 2 - t|^2, weight relative to beta.
class MidpointAnchorEnergy : public QuadraticTerm {
 public:
  MidpointAnchorEnergy(std::vector<MidpointAnchor> anchors, int num_vertices, double weight)
      : QuadraticTerm(num_vertices, weight, true), anchors_(std::move(anchors)) {}
  std::string name() const override { return "midpoint_anchor"; }
  double add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                       ResidualSum* sum) const override {
    double energy = 0;
    for (const MidpointAnchor& a : anchors_)
      energy += sum->add<3, 3>(MidpointAnchorResidual(a.offset), {a.m, a.a, a.b});
    return energy;
  }

 private:
  std::vector<MidpointAnchor> anchors_;
};

// A 7 x 3 x 3 bar whose last corner vertex is pulled sideways off the middle of
// its first two corners.
struct AnchoredBar : test::ProblemFixture {
  MidpointAnchor anchor{0, 0, 0, Eigen::Vector3d(0, 1.5, 0)};
  explicit AnchoredBar(bool with_anchor) : ProblemFixture(test::grid_tet_mesh(6, 2, 2, 0.5)) {
    anchor.m = n - 1;
    anchor.a = 0;
    anchor.b = 6;
    anchor.offset += mesh.V.row(anchor.m) - 0.5 * (mesh.V.row(anchor.a) + mesh.V.row(anchor.b));
    if (with_anchor)
      problem.terms.push_back(
          std::make_unique<MidpointAnchorEnergy>(std::vector<MidpointAnchor>{anchor}, n, 1.0));
    lambda2 = fiedler_value(beta_laplacian(problem));
  }
  double anchor_error(const Eigen::MatrixX3d& Q) const {
    return (Q.row(anchor.m) - 0.5 * (Q.row(anchor.a) + Q.row(anchor.b)) - anchor.offset.transpose())
        .norm();
  }
};

// One cascade at a fixed beta, run to convergence.
CascadeResult solve(const AnchoredBar& f, const std::string& method) {
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  options.num_cascades = 1;
  options.k_iter = 100000;
  options.epsilon = 1e-13;
  options.edge_ratio_band = {-1, -1};  // never in band: no early stop
  BackendOptions backend_options;
  backend_options.method = method;
  backend_options.linear_solver.method = "direct";
  backend_options.ceres.function_tolerance = 1e-15;
  backend_options.ceres.gradient_tolerance = 1e-14;
  const std::unique_ptr<CascadeBackend> backend = make_backend(backend_options, f.problem);
  return run_cascade(f.problem, *backend, options);
}

TEST(CustomTerm, BothBackendsMinimiseATermDefinedInATestFile) {
  const AnchoredBar f(true);
  const CascadeResult local_global = solve(f, "local_global"), ceres = solve(f, "ceres");
  EXPECT_NEAR(local_global.final_energy, ceres.final_energy,
              1e-6 * std::abs(local_global.final_energy));
  // The term acts: the anchored vertex ends near its target, far nearer than without it.
  const AnchoredBar without(false);
  const double free_error = without.anchor_error(solve(without, "ceres").positions);
  EXPECT_LT(f.anchor_error(local_global.positions), 0.5 * free_error);
  EXPECT_LT(f.anchor_error(ceres.positions), 0.5 * free_error);
}

}  // namespace
}  // namespace unfold
