// Run options: defaults (equal to configs/default.yaml), loading from YAML
// with overrides, validation and the effective configuration as YAML.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "energies/energy_terms.h"
#include "energies/soft_joint_factors.h"
#include "mesh/untangle_tets.h"
#include "metrics/geodesic_error.h"
#include "metrics/stretch_error.h"
#include "solvers/cascade.h"
#include "solvers/ceres_backend.h"
#include "solvers/integrate_rotation_field.h"
#include "solvers/local_global.h"
#include "solvers/lsmds.h"
#include "solvers/match_canonical_forms.h"
#include "solvers/scf.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

/// What unfold does when not told otherwise (configs/default.yaml): the
/// surface solved to convergence at a low beta, its rotations integrated on
/// the tet mesh, the unfolded shape's tets where the input touches itself,
/// stretch weighted by area (docs/method.md, pose invariance, contact,
/// meshing). The members' initializers are the paper's parameters
/// (paper_options()); the default constructor sets the default method over them.
struct Options {
  struct PapersParameters {};
  Options();
  /// The members' initializers alone: the paper's parameters.
  explicit Options(PapersParameters) {}
  std::string method = "local_global";
  int target_vertices = 0;
  int surface_solve_hops = 0;  ///< simplify.surface_solve_hops: the surface solved on clusters
  /// simplify.surface_solve_vertices: with surface_solve_hops 0, a larger
  /// surface solved on clusters, the fewest edges across that leave at most this many
  int surface_solve_vertices = 0;
  TetOptions tet;
  bool fallback_surface_graph = false;  ///< no tet mesh possible: unfold the surface edge graph
  std::string components = "refuse";    ///< several components: "refuse" or "separately"
  std::string domain = "volume";        ///< "volume" (tet mesh, the paper's) or "surface"
  /// domain surface: the tet mesh of the "input" or of the surface solve ("unfolded",
  /// which joins no parts that touch in the input; solvers/tetrahedralize_unfolded.h);
  /// "auto": unfolded (robust route) wherever there is a surface solve and
  /// tet.route is not conforming, else input;
  /// "contact": unfolded (robust route) where the input's tets bridge a contact, else input
  std::string tet_shape = "input";
  /// shape contact: a tet edge bridges a contact when its ends are farther apart
  /// along the surface than this times sqrt(area) (solvers/contact_bridges.h)
  double contact_geodesic = 0.05;
  std::string beta_mode = "relative";
  double beta_value = 1.5;
  bool raise_beta_to_bound = true;    ///< a starting beta below the bound is raised above it
  CascadeOptions cascade;             ///< cascade.beta is derived from beta_mode / beta_value
  LinearSolverOptions linear_solver;  ///< the global step's solver (method local_global)
  IntegrateOptions integrate;         ///< after the cascade (pose invariance)
  SoftenOptions soften;               ///< the cascade again with its joints softened
  UntangleOptions untangle;           ///< the canonical tets' inverted ones mended
  EnergyOptions energy;
  CeresOptions ceres;
  LsmdsOptions lsmds;                                              ///< method: lsmds only
  ScfOptions scf;                                                  ///< method: scf only
  std::vector<std::string> metrics = {"E_rig", "E_str", "E_geo"};  ///< the metrics computed
  /// E_geo is left out above this many tet vertices, with the reason in the
  /// result (0: no limit; the unfold command's default is 20,000)
  int geodesic_max_vertices = 0;
  StretchErrorOptions stretch_metric;
  GeodesicErrorOptions geodesic_metric;
  MatchOptions match;  ///< unfold_match only (solvers/match_canonical_forms.h)
  int threads = 0;
};

/// The paper's method and parameters (configs/paper.yaml): the energy on the
/// tet mesh, beta 1.5 n / lambda_2 and four cascades of at most 15 iterations
/// (Algorithm 1), no integration.
Options paper_options();

/// Options from a YAML file (or the defaults when config_path is empty), then
/// the overrides (YAML path -> value text, e.g. "cascade.k_iter" -> "20").
/// The file's keys override the defaults, or the paper's parameters when it
/// says `base: paper` (the baselines' and the paper's variants' configs).
/// @throws UsageError naming the key for an unreadable file, invalid YAML, an
///         unknown key, a wrong type or an out-of-range value
Options load_options(const std::string& config_path,
                     const std::map<std::string, std::string>& overrides = {});

/// Checks ranges and choices. @throws UsageError naming the key.
void validate_options(const Options& options);

/// Whether options.metrics asks for the metric `name` ("E_rig", "E_str" or "E_geo").
bool computes_metric(const Options& options, const std::string& name);

/// Whether the tet mesh is made from the surface solve's unfolded shape
/// whatever the input (tetrahedralize.shape: unfolded, or auto with a route
/// other than conforming; domain: surface and a method other than lsmds and scf).
bool tets_from_unfolded(const Options& options);

/// Whether the input's tets are made and then, if they bridge a contact, the
/// unfolded shape's instead (tetrahedralize.shape: contact with domain: surface).
bool tets_from_unfolded_on_contact(const Options& options);

/// The options as a YAML document with every key (the effective configuration).
std::string options_to_yaml(const Options& options);

}  // namespace unfold
