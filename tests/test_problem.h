// An UnfoldProblem on a small tet mesh, for solver and energy tests.
#pragma once

#include <memory>

#include "energies/energy_terms.h"
#include "solvers/fiedler_value.h"
#include "solvers/unfold_problem.h"
#include "test_meshes.h"

namespace unfold::test {

struct ProblemFixture {
  TetMesh mesh;
  std::unique_ptr<EdgeGraph> graph;  // the terms refer to it: keep its address fixed
  UnfoldProblem problem;
  int n = 0;
  double lambda2 = 0;

  explicit ProblemFixture(TetMesh tets, const EnergyOptions& energy = {})
      : mesh(std::move(tets)),
        graph(std::make_unique<EdgeGraph>(build_edge_graph(int(mesh.V.rows()), mesh.T))) {
    problem.graph = graph.get();
    problem.rest = mesh.V;
    problem.terms = make_energy_terms(mesh, *graph, energy);
    n = int(mesh.V.rows());
    lambda2 = fiedler_value(beta_laplacian(problem));
  }
};

}  // namespace unfold::test
