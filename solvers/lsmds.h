// The LSMDS baseline (Elad and Kimmel's least-squares MDS, the paper's
// comparison): positions whose Euclidean distances match the rest shape's
// tet-edge-graph geodesics in the least-squares sense, minimised by SMACOF
// (iterated Guttman transforms, stress non-increasing), all pair weights 1,
// initialised from the rest positions.
//
// Exact for meshes up to LsmdsOptions::exact_limit vertices (all n^2 pairs).
// Above it, landmark SMACOF: the stress keeps only the pairs with at least one
// of k landmarks (farthest-point samples of the geodesic metric), every vertex
// is still updated, and the weighted Guttman transform has a closed form
// (docs/baselines.md), so an iteration costs O(k n) and the geodesics k
// Dijkstra runs instead of n.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

struct LsmdsOptions {
  int exact_limit = 4000;    ///< all pairs up to this many vertices, landmarks above
  int landmarks = 400;       ///< landmark count k above the exact limit
  int max_iterations = 500;  ///< Guttman transforms at most
  double tolerance = 1e-6;   ///< stop when the relative stress decrease is below this
};

/// Target distances of the pairs that carry weight 1: rows(a, j) = d(landmarks[a], j).
/// The exact variant has landmarks = 0..n-1.
struct LandmarkDistances {
  std::vector<int> landmarks;
  Eigen::MatrixXd rows;  ///< k x n
};

struct LsmdsResult {
  Eigen::MatrixX3d positions;  ///< zero mean
  std::vector<double> stress;  ///< sum over weighted pairs of (d_ij - |x_i - x_j|)^2, per iterate
  int iterations = 0;          ///< Guttman transforms applied
  bool exact = true;           ///< false: landmark variant
  bool converged = false;      ///< false: stopped by max_iterations
};

/// Checks the option values. @throws UsageError naming the lsmds.* key
void validate_lsmds_options(const LsmdsOptions& options);

/// Tet-edge-graph geodesics of the rest shape P: all rows up to
/// options.exact_limit vertices, else options.landmarks farthest-point rows
/// (starting at vertex 0).
/// @throws UsageError if P does not match the graph,
///         NumericalError if the graph is disconnected
LandmarkDistances lsmds_distances(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                  const LsmdsOptions& options);

/// The stress of X and its Guttman transform: the minimiser of the stress's
/// majorizer at X (zero mean). @pre X has as many rows as distances.rows has columns
double guttman_transform(const LandmarkDistances& distances, const Eigen::MatrixX3d& X,
                         Eigen::MatrixX3d* next);

/// Called with k >= 1, the positions after k transforms and their stress.
using LsmdsCallback = std::function<void(int k, const Eigen::MatrixX3d& X, double stress)>;

/// SMACOF from X0 until the relative stress decrease falls below
/// options.tolerance or options.max_iterations transforms.
/// @param on_iterate if set, called once per iterate after the first transform
/// @throws UsageError if X0 does not match distances
LsmdsResult smacof(const LandmarkDistances& distances, const Eigen::MatrixX3d& X0,
                   const LsmdsOptions& options, const LsmdsCallback& on_iterate = {});

/// lsmds_distances, then smacof from P.
/// @throws as lsmds_distances
LsmdsResult lsmds(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const LsmdsOptions& options,
                  const LsmdsCallback& on_iterate = {});

}  // namespace unfold
