#include "energies/energy_terms.h"

#include "core/errors.h"
#include "energies/arap_energy.h"
#include "energies/cotangent_weights.h"
#include "energies/distance_clusters.h"
#include "energies/distance_spread_energy.h"
#include "energies/edge_length_energy.h"
#include "energies/read_user_pairs.h"
#include "energies/stretch_energy.h"
#include "energies/user_pairs_energy.h"
#include "energies/volume_energy.h"
#include "mesh/lumped_masses.h"

namespace unfold {

namespace {

Eigen::VectorXd stretch_masses(const TetMesh& tets, const EnergyOptions& options,
                               const Eigen::VectorXd& masses) {
  if (options.stretch_masses == "uniform") return {};
  if (options.stretch_masses != "lumped")
    throw UsageError("config key 'stretch.masses' must be uniform or lumped, got '" +
                     options.stretch_masses + "'");
  if (masses.size() > 0) return masses;
  if (tets.T.rows() == 0)
    throw UsageError(
        "stretch.masses: lumped needs the surface's vertex areas on a mesh without tets");
  return stretch_mass_shares(lumped_masses(tets.V, tets.T), options);
}

}  // namespace

Eigen::VectorXd stretch_mass_shares(Eigen::VectorXd shares, const EnergyOptions& options) {
  // At 1 the shares themselves, bit for bit.
  if (options.stretch_mass_power != 1) shares = shares.array().pow(options.stretch_mass_power);
  return shares;
}

EnergyTerms make_energy_terms(const TetMesh& tets, const std::shared_ptr<const EdgeGraph>& graph,
                              const EnergyOptions& options, const Eigen::VectorXd& masses,
                              const std::vector<double>& arap_factors,
                              const DistanceClusters* clusters) {
  EnergyTerms terms;
  const Eigen::VectorXd spread_masses = stretch_masses(tets, options, masses);
  terms.push_back(std::make_unique<StretchEnergy>(
      graph, options.stretch_weight, spread_masses,
      options.stretch_local > 0
          ? spread_regions(tets.V, *graph,
                           {options.stretch_local, options.stretch_local_radius,
                            options.stretch_local_regions})
          : SpreadRegions{}));
  if (options.stretch_distance > 0) {
    DistanceClusters made;
    if (!clusters) {
      made = make_distance_clusters(tets.V, *graph, options.stretch_distance_clusters);
      clusters = &made;
    } else if (clusters->cell_of.size() != size_t(graph->num_vertices)) {
      throw UsageError("make_energy_terms: the given clusters are not one per graph vertex");
    }
    terms.push_back(std::make_unique<DistanceSpreadEnergy>(
        clusters->cell_of, clusters->count, spread_masses,
        distance_spread_weight(tets.V, spread_masses, options.stretch_distance)));
  }
  std::vector<double> weights;
  if (options.arap_weights == "uniform")
    weights.assign(size_t(graph->num_edges()), 1.0);
  else if (options.arap_weights == "cotangent" && tets.T.rows() > 0)
    weights = cotangent_weights(tets.V, tets.T, *graph);
  else if (options.arap_weights == "cotangent")
    throw UsageError(
        "config key 'arap.weights' is cotangent, but there are no tets to take cotangent "
        "weights from (surface edge graph); use uniform");
  else
    throw UsageError("config key 'arap.weights' must be uniform or cotangent, got '" +
                     options.arap_weights + "'");
  if (!arap_factors.empty()) {
    if (arap_factors.size() != weights.size())
      throw UsageError("make_energy_terms: arap_factors needs one factor per graph edge");
    for (size_t e = 0; e < weights.size(); ++e) weights[e] *= arap_factors[e];
  }
  if (options.arap_weight > 0)
    terms.push_back(std::make_unique<ArapEnergy>(graph, tets.V, weights, options.arap_weight));
  if (options.edge_length_weight > 0)
    terms.push_back(std::make_unique<EdgeLengthEnergy>(graph, tets.V, options.edge_length_weight));
  if (!options.user_pairs_file.empty())
    terms.push_back(std::make_unique<UserPairsEnergy>(
        read_user_pairs(options.user_pairs_file, tets.num_surface_vertices), int(tets.V.rows()),
        options.user_pairs_gamma));
  if (options.volume_weight > 0)
    terms.push_back(std::make_unique<VolumeEnergy>(tets.V, tets.T, options.volume_weight));
  return terms;
}

}  // namespace unfold
