// The whole pipeline on one surface: check, simplify, tetrahedralize, unfold,
// measure. Apps call this and do the file input/output around it.
#pragma once

#include <string>
#include <vector>

#include "config/options.h"
#include "mesh/curve_skeleton.h"
#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "mesh/untangle_tets.h"
#include "metrics/surface_damage.h"
#include "metrics/surface_folds.h"
#include "solvers/cascade.h"
#include "solvers/local_global.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

/// E_rig, E_str and E_geo are NaN when not computed (options.metrics), which
/// the metrics JSON writes as null.
struct UnfoldMetrics {
  double E_rig = 0;         ///< Eq. 8 over the tet edges
  double E_str = 0;         ///< Eq. 9 over the tet vertices
  bool E_str_exact = true;  ///< false: estimated from stretch_samples random pairs
  double E_geo = 0;         ///< Eq. 10 with tet-edge-graph geodesics of the rest shape
  bool E_geo_exact = true;  ///< false: estimated from geodesic_landmarks source rows
  /// Eq. 10 over the surface alone (its edges' geodesics, the canonical surface's
  /// distances): the same vertices and geodesics whatever tets a method made, so it
  /// compares methods where E_geo also weighs their interior vertices
  /// (docs/method.md, metrics); computed with E_geo, NaN when not (or the surface's
  /// edges fall apart)
  double E_geo_surface = 0;
  /// why E_geo was left out though metrics.compute lists it (above
  /// metrics.geodesic_max_vertices) and how to ask for it; empty otherwise
  std::string E_geo_skipped;
  int inverted_tets = 0;  ///< tetrahedra whose orientation flipped (from how they were made)
  /// the canonical surface's edges against the input's at its area
  /// (metrics/surface_damage.h): always computed, whatever metrics.compute lists
  SurfaceDamage damage;
  /// the canonical surface's bends against the input's (metrics/surface_folds.h):
  /// folds that keep edge lengths, which `damage` cannot see; always computed
  SurfaceFolds folds;
  double seconds = 0;
  /// E_rig's term of each tet vertex (RigidityError); NaN when E_rig is not computed
  Eigen::VectorXd rigidity_per_vertex;
};

/// One stage's wall seconds, as the stage driver measured it
/// (pipeline/run_stages.h).
struct StageTime {
  std::string name;
  double seconds = 0;
};

/// A surface checked, simplified if asked, and tetrahedralized: what every
/// solver run on it shares.
struct PreparedMesh {
  SurfaceMesh surface;  ///< the surface unfolded (the input, or its simplification)
  /// the input's tet mesh; the surface alone (no tets) when the options
  /// tetrahedralize the unfolded shape instead (tets_deferred)
  TetMesh tets;
  bool tets_deferred = false;
  /// given tets (prepare_mesh_from_tets) made on the unfolded shape: where they
  /// were made, rows as tets.V's; the unfolded shape's route then takes them
  /// instead of making its own; else empty
  Eigen::MatrixX3d unfolded_tet_positions;
  TetReport tet_report;
  std::vector<std::string> warnings;
  /// the preparation's stages (checks and simplification, contact, tets) in order
  std::vector<StageTime> stage_seconds;
  double seconds = 0;          ///< the preparation: its stages' seconds summed
  double seconds_contact = 0;  ///< shape contact: its intersecting faces checked for contact
};

struct UnfoldResult {
  SurfaceMesh surface;             ///< the surface unfolded (the input, or its simplification)
  SurfaceMesh canonical;           ///< same faces, canonical positions
  TetMesh tets;                    ///< rest tet mesh
  Eigen::MatrixX3d tet_canonical;  ///< canonical positions of every tet vertex
  /// tetrahedralize.shape: unfolded: the tet vertices where the tets were made
  /// (the surface solve's shape; metrics.inverted_tets is counted against it); else empty
  Eigen::MatrixX3d unfolded_tet_positions;
  TetReport tet_report;
  UntangleReport untangle;  ///< what untangle.sweeps did to the canonical tets (all 0: off)
  int num_edges = 0;
  double lambda2 = 0;
  double beta_requested = 0;  ///< starting beta from the options (beta.mode, beta.value)
  double beta_start = 0;      ///< starting beta used: beta_requested, or raised above the bound
  bool beta_raised = false;   ///< beta_requested was below n/lambda_2 - 1 and was raised
  CascadeResult cascade;
  UnfoldMetrics metrics;
  std::string linear_solver;  ///< the global step's solver: direct, iterative, ceres ("" for lsmds)
  int amg_levels = 0;         ///< iterative: levels of the AMG hierarchy
  double seconds_amg = 0;     ///< iterative: building the AMG hierarchy
  CgStats cg;                 ///< iterative: what the CG global steps did
  double seconds_lambda2 = 0;  ///< the solver's setup (AMG hierarchy included) and lambda_2
  double seconds_cascade = 0;  ///< the cascade (its last solve, for domain: surface)
  double seconds_unfold = 0;   ///< lambda_2 and the cascade, and what surrounds them
  double seconds_prepare = 0;  ///< prepare_mesh (the input's tets, when made, included)
  /// shape auto: finding contact (intersecting faces far apart, the input's
  /// tets bridging it), in prepare_mesh and after
  double seconds_contact = 0;
  double seconds_interior = 0;     ///< domain: surface: the interior placed by ARAP
  double seconds_integration = 0;  ///< integrate: the rotation field integrated (one step)
  double seconds_anchored = 0;     ///< integrate: the anchored ARAP steps after it
  int anchored_steps = 0;  ///< integrate: the anchored steps taken (several components: most)
  /// integrate: the anchored steps stopped by their tolerance (or when a step no
  /// longer lowered their energy), not by integrate.iterations; true when none ran
  bool anchored_converged = true;
  std::vector<std::string> warnings;
  /// every stage run, the preparation's included, in order; the seconds_* fields
  /// above are sums of these (pipeline/run_stages.h)
  std::vector<StageTime> stage_seconds;
  CurveSkeleton skeleton;               ///< method scf: the input's curve skeleton, else empty
  Eigen::MatrixX3d skeleton_canonical;  ///< method scf: its straightened nodes, placed as canonical
};

/// Checks, simplifies (options.target_vertices) and tetrahedralizes a surface.
/// With options.fallback_surface_graph, an open surface or one that cannot be
/// tetrahedralized yields the surface alone (tets.T empty, route
/// "surface_graph", a warning): it is then unfolded on its own edge graph.
/// @throws InputError for a surface that fails the checks (several components
///         included), NumericalError when tetrahedralization fails (without
///         the fallback), UsageError for bad options
PreparedMesh prepare_mesh(const SurfaceMesh& input, const Options& options);

/// Unfolds a prepared mesh with the options' energy terms, backend and cascade.
/// @throws NumericalError when the solve fails, InputError for a bad pairs file,
///         UsageError for bad options
UnfoldResult unfold_prepared(const PreparedMesh& prepared, const Options& options);

/// Unfolds a surface into its canonical pose: prepare_mesh, then
/// unfold_prepared. With options.components == "separately" a surface of
/// several components is unfolded one component at a time
/// (unfold_components_separately).
/// @param surface  the input surface, as read (it is checked here)
/// @param options  validated options (load_options)
/// @throws InputError for a surface that fails the checks, NumericalError when
///         tetrahedralization or the solve fails, UsageError for bad options
UnfoldResult unfold_surface(const SurfaceMesh& surface, const Options& options);

}  // namespace unfold
