// The set of energy terms a run minimises, built from the config.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "energies/distance_clusters.h"
#include "energies/energy_term.h"
#include "mesh/edge_graph.h"
#include "mesh/tet_mesh.h"

namespace unfold {

struct EnergyOptions {
  double stretch_weight = 1.0;             ///< k_ij (paper: 1)
  std::string stretch_masses = "uniform";  ///< uniform (paper: every vertex 1) or lumped
  double stretch_mass_power = 1.0;         ///< lumped: the shares to this power, in [0, 1]
  double stretch_local = 0.0;              ///< share of the spread within regions, in [0, 1)
  double stretch_local_radius = 0.3;       ///< the regions' width, times the geodesic diameter
  int stretch_local_regions = 32;          ///< how many regions
  double stretch_distance =
      0.0;  ///< spread by distances (times the paper's squared one's pull); 0: off
  int stretch_distance_clusters = 512;   ///< its clusters (graph-Voronoi cells of the rest shape)
  double arap_weight = 1.0;              ///< ARAP weight relative to beta (paper: 1)
  std::string arap_weights = "uniform";  ///< w_ij: uniform (paper) or cotangent
  std::string user_pairs_file;           ///< pair constraints (Eq. 11); empty: none
  double user_pairs_gamma = 1.0;         ///< gamma relative to beta (paper: gamma = beta)
  double volume_weight = 0.0;            ///< tet volume term relative to beta; 0: off
  double edge_length_weight = 0.0;       ///< edge-length springs relative to beta; 0: off
};

using EnergyTerms = std::vector<std::unique_ptr<EnergyTerm>>;

/// stretch.masses lumped: the stretch term's masses from the vertices' shares of
/// the volume or area (lumped masses), each to options.stretch_mass_power.
/// @param shares positive lumped masses (any scale)
Eigen::VectorXd stretch_mass_shares(Eigen::VectorXd shares, const EnergyOptions& options);

/// The terms enabled by `options` on a tet mesh: stretch, and ARAP, edge
/// lengths, user pairs and volume when configured (weight > 0, a pairs file). The terms
/// share `graph`.
/// @param graph  the edge graph of `tets` (of its surface when tets.T is empty)
/// @param masses the stretch term's vertex masses with stretch_masses: lumped
///        (stretch_mass_shares); when empty, those of the lumped volumes of tets.T
/// @param arap_factors per graph edge, factors of the ARAP weights (soft joints,
///        energies/soft_joint_factors.h); empty: none
/// @param clusters the spread by distances' clusters (stretch.distance > 0), made
///        already for this mesh and options.stretch_distance_clusters; null: made here
/// @throws UsageError for an unknown arap_weights or stretch_masses, lumped masses
///         asked of a mesh without tets and none given, or arap_factors not one per
///         edge; InputError for a bad pairs file
EnergyTerms make_energy_terms(const TetMesh& tets, const std::shared_ptr<const EdgeGraph>& graph,
                              const EnergyOptions& options,
                              const Eigen::VectorXd& masses = Eigen::VectorXd(),
                              const std::vector<double>& arap_factors = {},
                              const DistanceClusters* clusters = nullptr);

}  // namespace unfold
