// What a method's stages hand each other (pipeline/unfold_steps.h): the mesh
// being prepared, the result being filled, and the stages' typed outputs that
// later stages take as inputs.
#pragma once

#include <future>
#include <optional>

#include "config/options.h"
#include "mesh/coarsen_surface.h"
#include "metrics/geodesic_error.h"
#include "pipeline/unfold_surface.h"
#include "solvers/integrate_rotation_field.h"
#include "stages/setup_cascade.h"
#include "stages/solve_edge_graph.h"

namespace unfold {

struct UnfoldState {
  explicit UnfoldState(const Options& o) : options(o) {}
  const Options& options;

  const SurfaceMesh* input = nullptr;  ///< the preparation's input
  bool open = false;                   ///< the surface has holes no tetrahedralization route closes
  int known_intersections = -1;        ///< intersecting face pairs found by the contact check
  /// the mesh being unfolded: the preparation's (prepare_mesh returns it), its
  /// tets replaced by the unfolded shape's where a method makes those
  PreparedMesh mesh;
  /// what the unfolding found; the metrics stage moves mesh's surface, tets,
  /// report and warnings (first) into it
  UnfoldResult result;
  bool contact_bridge = false;              ///< some input tet bridges a contact (contact check)
  SolveEdges edges;                         ///< the tets' edges every stage after them solves on
  std::future<GeodesicRows> geodesic_rows;  ///< E_geo's rows, computed beside the solve
  /// E_geo_surface's rows, computed beside the solve (no sources: the surface's edges
  /// fall apart); none: computed with the metrics
  std::optional<GeodesicRows> surface_geodesic_rows;
  /// where the cascade solves: the surface (domain surface) or the tets and their edges
  TetMesh cascade_mesh;
  SolveEdges cascade_edges;
  /// simplify.surface_solve_hops: the coarse graph the surface stages solve on
  /// (cascade_mesh and cascade_edges are its), and its masses; else empty
  SurfaceCoarsening coarsening;
  CascadeSetup setup;               ///< lambda_2 and beta, for the next cascade
  std::string first_solver;         ///< the first solve's linear solver (soft joints reuse it)
  EarlierSetup first_setup;         ///< what the first solve's setup hands on to the soft joints'
  Eigen::MatrixX3d first_solution;  ///< soft joints: the first solve's positions
  int first_iterations = 0;
  double anchor_lambda2 = 0;  ///< the integration's anchor unit
  IntegratedRotations integrated;
};

}  // namespace unfold
