#include "solvers/unfold_problem.h"

#include <algorithm>

#include "core/parallel.h"
#include "energies/rotation_term.h"
#include "geometry/best_rotation.h"

namespace unfold {

UnfoldProblem make_unfold_problem(const TetMesh& mesh, EdgeGraph graph,
                                  const EnergyOptions& options, const Eigen::VectorXd& masses,
                                  const std::vector<double>& arap_factors,
                                  std::shared_ptr<const DistanceClusters> clusters) {
  UnfoldProblem problem;
  problem.graph = std::make_shared<const EdgeGraph>(std::move(graph));
  problem.rest = mesh.V;
  if (options.stretch_distance > 0)
    problem.distance_clusters =
        clusters ? std::move(clusters)
                 : std::make_shared<const DistanceClusters>(make_distance_clusters(
                       mesh.V, *problem.graph, options.stretch_distance_clusters));
  problem.terms = make_energy_terms(mesh, problem.graph, options, masses, arap_factors,
                                    problem.distance_clusters.get());
  return problem;
}

double total_energy(const UnfoldProblem& problem, const Eigen::MatrixX3d& Q, const Rotations& R,
                    double beta, Eigen::MatrixX3d* grad) {
  if (grad) grad->setZero(problem.num_vertices(), 3);
  double energy = 0;
  for (const auto& term : problem.terms) energy += term->evaluate(Q, R, term->weight(beta), grad);
  return energy;
}

void fit_rotations(const UnfoldProblem& problem, const Eigen::MatrixX3d& Q, double beta,
                   Rotations* R, std::vector<Eigen::Matrix3d>* covariances) {
  const int n = problem.num_vertices();
  std::vector<Eigen::Matrix3d> local;
  std::vector<Eigen::Matrix3d>& S = covariances ? *covariances : local;
  S.resize(size_t(n));
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int i = 0; i < n; ++i) S[size_t(i)].setZero();
  bool any = false;
  for (const auto& term : problem.terms)
    if (const auto* rotation_term = dynamic_cast<const RotationTerm*>(term.get())) {
      rotation_term->add_rotation_covariance(Q, term->weight(beta), &S);
      any = true;
    }
  // The rotations of the previous call, when there are n of them, are
  // starting guesses: cells turn little from one iteration to the next.
  const bool warm = R->size() == size_t(n);
  R->resize(size_t(n));
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int first = 0; first < n; first += kRotationPacket) {
    const Eigen::Matrix3d* cov[kRotationPacket];
    Eigen::Matrix3d* rotation[kRotationPacket];
    int count = 0;
    for (int i = first; i < std::min(n, first + kRotationPacket); ++i) {
      Eigen::Matrix3d& r = (*R)[size_t(i)];
      if (!any || S[size_t(i)].isZero(0)) {
        r.setIdentity();
      } else if (!warm) {
        r = best_rotation(S[size_t(i)]);
      } else {
        cov[count] = &S[size_t(i)];
        rotation[count++] = &r;
      }
    }
    best_rotations_from_guesses(cov, rotation, count);
  }
}

Eigen::SparseMatrix<double> beta_laplacian(const UnfoldProblem& problem) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(size_t(problem.num_vertices()) + 4 * size_t(problem.graph->num_edges()));
  for (const auto& term : problem.terms)
    if (term->scales_with_beta()) term->add_growth_hessian(0.5 * term->weight(1.0), &triplets);
  Eigen::SparseMatrix<double> L(problem.num_vertices(), problem.num_vertices());
  L.setFromTriplets(triplets.begin(), triplets.end());
  return L;
}

}  // namespace unfold
