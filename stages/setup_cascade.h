// Stage: what a cascade needs before its first step. The energy problem, the
// linear solver decided (direct or iterative, for linear_solver.method auto),
// lambda_2 of the problem's Laplacian and the starting beta from it. The
// backend's own setup runs beside lambda_2 where the two would each use one
// thread (the direct solver): solve_cascade collects it.
#pragma once

#include <Eigen/Core>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "mesh/edge_graph.h"
#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "solvers/beta_schedule.h"
#include "solvers/cascade.h"
#include "solvers/make_backend.h"
#include "solvers/smoothed_aggregation.h"
#include "solvers/unfold_problem.h"

namespace unfold {

struct CascadeSetupOptions {
  /// method (local_global, ceres, dpmu), the linear solver (method auto decided
  /// by setup_cascade), ceres
  BackendOptions backend;
  EnergyOptions energy;
  std::string beta_mode = "relative";  ///< beta.mode: relative (times n / lambda_2) or absolute
  double beta_value = 1.5;
  bool raise_beta_to_bound = true;  ///< a starting beta below the bound is raised above it
};

/// What a setup hands on to a later one on the same mesh and graph with other
/// weights (soft joints), so that it is not made again.
struct EarlierSetup {
  std::shared_ptr<const DistanceClusters> clusters;  ///< the spread by distances' (or null)
  Eigen::VectorXd fiedler_vector;  ///< direct solver: lambda_2's eigenvector, the next one's start
};

struct CascadeSetup {
  std::unique_ptr<UnfoldProblem> problem;  ///< on the heap: the backend's setup reads it
  /// options.backend, the linear solver decided (direct or iterative)
  BackendOptions backend_options;
  std::shared_ptr<AmgData> amg;  ///< iterative: the AMG hierarchy, for lambda_2 and the backend
  int amg_levels = 0;            ///< iterative: its levels
  double seconds_amg = 0;        ///< iterative: its build (on another thread when speculative)
  double lambda2 = 0;            ///< of L x = lambda M x, the problem's Laplacian and masses
  BetaStart beta;
  /// direct: the backend being set up meanwhile; invalid: solve_cascade sets it up
  std::future<std::unique_ptr<CascadeBackend>> backend;
  std::vector<std::string> warnings;  ///< beta raised to the bound
  Eigen::VectorXd fiedler_vector;     ///< direct: lambda_2's eigenvector; iterative: empty
};

/// Sets up the cascade of `options` on the vertices and edges of `mesh`.
/// @param graph         the edge graph the energy lives on (mesh's tets', or the
///                      surface's triangles' when mesh has no tets), connected
/// @param surface       the surface of mesh: its areas are the masses when mesh has no tets
/// @param arap_factors  factors of the ARAP weights per edge of graph; empty: none
/// @param masses        stretch.masses lumped: the vertices' masses when mesh is
///                      neither tets nor surface (a coarse graph of the surface); empty:
///                      mesh's own
/// @param earlier       what an earlier setup on the same mesh and graph hands on; null:
///                      none, everything made here
/// @throws NumericalError when lambda_2 cannot be found, UsageError for bad options
CascadeSetup setup_cascade(const EdgeGraph& graph, const TetMesh& mesh, const SurfaceMesh& surface,
                           const CascadeSetupOptions& options,
                           const std::vector<double>& arap_factors = {},
                           const Eigen::VectorXd& masses = Eigen::VectorXd(),
                           const EarlierSetup* earlier = nullptr);

}  // namespace unfold
