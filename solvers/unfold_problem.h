// The problem every solver minimises: the tet mesh's edge graph, the rest
// positions and the energy terms. Solvers see terms only through this and the
// terms' capability interfaces (energies/energy_term.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "energies/energy_terms.h"
#include "geometry/rotations.h"
#include "mesh/edge_graph.h"
#include "mesh/tet_mesh.h"

namespace unfold {

struct UnfoldProblem {
  std::shared_ptr<const EdgeGraph> graph;  ///< shared with the terms that read it
  Eigen::MatrixX3d rest;
  EnergyTerms terms;
  /// the spread by distances' clusters (stretch.distance > 0), for a problem on
  /// the same mesh with other weights to share (soft joints); null: no such term
  std::shared_ptr<const DistanceClusters> distance_clusters;
  int num_vertices() const { return graph->num_vertices; }
};

/// The problem of the terms `options` enable on `mesh`, owning its graph.
/// @param graph  the edge graph of mesh (of its surface when mesh.T is empty)
/// @param masses, arap_factors as make_energy_terms
/// @param clusters another problem's distance_clusters on this mesh and graph; null: made
///        here when options.stretch_distance > 0
/// @throws as make_energy_terms
UnfoldProblem make_unfold_problem(const TetMesh& mesh, EdgeGraph graph,
                                  const EnergyOptions& options,
                                  const Eigen::VectorXd& masses = Eigen::VectorXd(),
                                  const std::vector<double>& arap_factors = {},
                                  std::shared_ptr<const DistanceClusters> clusters = nullptr);

/// E(Q; R) = sum_t w_t(beta) e_t(Q; R); with grad, its gradient at fixed R
/// (grad is resized to n x 3). At the optimal R (fit_rotations) this is also
/// the gradient of min_R E(Q; R), by the envelope theorem.
double total_energy(const UnfoldProblem& problem, const Eigen::MatrixX3d& Q, const Rotations& R,
                    double beta, Eigen::MatrixX3d* grad = nullptr);

/// The local step: per vertex, the rotation minimising the rotation terms
/// (energies/rotation_term.h) at beta (their weighted cell covariances summed), in parallel over
/// vertices. When R holds n rotations already (the previous iteration's), they
/// are refined from (best_rotation with a guess); the result is the same to ~1e-12.
/// @param covariances optional buffer for the n cell covariances, so that
///        repeated calls allocate nothing
void fit_rotations(const UnfoldProblem& problem, const Eigen::MatrixX3d& Q, double beta,
                   Rotations* R, std::vector<Eigen::Matrix3d>* covariances = nullptr);

/// Half the summed growth Hessians (EnergyTerm::add_growth_hessian) of the terms that scale with
/// beta, at beta = 1: the Laplacian whose lambda_2 sets the scale of beta (for the paper's energy,
/// the graph Laplacian L; docs/method.md).
Eigen::SparseMatrix<double> beta_laplacian(const UnfoldProblem& problem);

}  // namespace unfold
