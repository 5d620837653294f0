// An UnfoldProblem on a small tet mesh, for solver and energy tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "energies/energy_terms.h"
#include "mesh/best_rotations.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "solvers/unfold_problem.h"
#include "test_meshes.h"

namespace unfold::test {

struct ProblemFixture {
  TetMesh mesh;
  UnfoldProblem problem;
  std::shared_ptr<const EdgeGraph> graph;  ///< the problem's
  int n = 0;
  double lambda2 = 0;

  explicit ProblemFixture(TetMesh tets, const EnergyOptions& energy = {})
      : mesh(std::move(tets)),
        problem(make_unfold_problem(mesh, build_edge_graph(int(mesh.V.rows()), mesh.T), energy)),
        graph(problem.graph) {
    n = int(mesh.V.rows());
    lambda2 = fiedler_value(beta_laplacian(problem));
  }
};

/// Both steps minimise the energy over their block of variables: within one
/// beta it never increases (up to roundoff).
inline void expect_energy_non_increasing_within_cascades(const CascadeResult& result) {
  for (size_t k = 1; k < result.history.size(); ++k) {
    if (result.history[k].cascade != result.history[k - 1].cascade) continue;
    EXPECT_LE(result.history[k].energy,
              result.history[k - 1].energy + 1e-9 * std::abs(result.history[k - 1].energy))
        << "iteration " << result.history[k].iteration;
  }
}

/// energy_from_covariances is total_energy at the rotations fit_rotations
/// fits, from the covariances it fitted them from: at a bent pose of f's mesh
/// and at a shape that is not zero-mean.
inline void expect_energy_from_covariances_is_the_total(const ProblemFixture& f, double beta) {
  LocalGlobalData data;
  local_global_precomputation(f.problem, &data, LinearSolverOptions{"direct"});
  local_global_set_beta(beta, &data);
  Eigen::MatrixX3d Q = f.mesh.V;
  for (int i = 0; i < f.n; ++i) Q(i, 1) += 0.2 * Q(i, 0) * Q(i, 0) + 0.05 * std::sin(3.0 * i);
  for (const double shift : {0.0, 0.5}) {
    const Eigen::MatrixX3d X = Q.rowwise() + Eigen::RowVector3d(shift, -shift, 0);
    Rotations R;
    std::vector<Eigen::Matrix3d> S;
    fit_rotations(f.problem, X, beta, &R, &S);
    const double total = total_energy(f.problem, X, R, beta);
    EXPECT_NEAR(energy_from_covariances(data, X, R, S), total, 1e-10 * std::abs(total))
        << "shift " << shift;
  }
}

/// f's mesh bent in its (x, y) plane, y += 0.1 x^2, and the rotations that fit it.
inline Eigen::MatrixX3d bent_pose(const ProblemFixture& f, Rotations* R) {
  Eigen::MatrixX3d bent = f.mesh.V;
  for (int i = 0; i < f.n; ++i) bent(i, 1) += 0.1 * bent(i, 0) * bent(i, 0);
  best_rotations(*f.graph, f.mesh.V, bent, R);
  return bent;
}

/// Prepares *data for exact global steps of f's problem at beta: method direct,
/// or iterative with CG to 1e-12.
inline void exact_global_steps(const ProblemFixture& f, const char* method, double beta,
                               LocalGlobalData* data) {
  LinearSolverOptions solver{method};
  solver.cg_tolerance = 1e-12;
  solver.cg_forcing = 0;
  local_global_precomputation(f.problem, data, solver);
  local_global_set_beta(beta, data);
}

/// From the rotations of a bent pose of f's mesh, one global step of each
/// linear solver (direct, and CG to 1e-12) zeroes the energy's gradient at
/// those rotations, and energy_after_global_step is the energy there: each
/// solves the step's whole system, its low-rank parts included.
inline void expect_global_steps_reach_the_minimiser(const ProblemFixture& f, double beta) {
  Rotations R;
  const Eigen::MatrixX3d bent = bent_pose(f, &R);
  Eigen::MatrixX3d grad_at_bent;
  total_energy(f.problem, bent, R, beta, &grad_at_bent);
  for (const char* method : {"direct", "iterative"}) {
    LocalGlobalData data;
    exact_global_steps(f, method, beta, &data);
    EXPECT_TRUE(energy_bounded(data)) << method;
    Eigen::MatrixX3d Q = bent.rowwise() - bent.colwise().mean();
    global_step(data, R, &Q);
    Eigen::MatrixX3d grad;
    const double energy = total_energy(f.problem, Q, R, beta, &grad);
    EXPECT_LT(grad.norm(), 1e-8 * grad_at_bent.norm()) << method;
    EXPECT_NEAR(energy_after_global_step(data, R, Q), energy, 1e-9 * std::abs(energy)) << method;
  }
}

}  // namespace unfold::test
