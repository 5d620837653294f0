// An UnfoldProblem on a small tet mesh, for solver and energy tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "energies/energy_terms.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
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

}  // namespace unfold::test
