// ZoomOut (Melzi et al., SIGGRAPH Asia 2019): refines a point-to-point map
// between two surfaces by alternating, over a growing spectral basis, the
// functional map the pointwise map induces and the pointwise map nearest to it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "solvers/laplace_beltrami_basis.h"

namespace unfold {

struct ZoomOutOptions {
  int start_size = 20;  ///< basis size of the first iteration
  int final_size = 80;  ///< basis size of the last iteration (<= both bases' sizes)
  int step = 4;         ///< basis growth per iteration
  /// the iterations before the last run on about this many vertices of each
  /// shape (every (n / samples)-th; the functional map's integrals weighted by
  /// the vertices' masses), the last on every vertex; 0: every vertex throughout
  int samples = 2000;
};

/// ZoomOut's iterations: for k = start_size, start_size + step, ..., final_size,
/// C = Phi_s^T M_s Phi_t[map] (k x k, the functional map that pulls target
/// functions back to the source), then map(i) = the target vertex j whose
/// spectral embedding Phi_t(j, :k) C^T is nearest to Phi_s(i, :k). Every
/// iteration on `samples` vertices of each shape (as in the paper's accelerated
/// variant); the functional map of the last size is returned, whose pointwise
/// map (pointwise_map) is the refined map. The maps' quality comes from the
/// initial map's: ZoomOut keeps its left/right choice and smooths the rest.
/// @param source, target Laplace-Beltrami bases (laplace_beltrami_basis) of
///        the two surfaces, at least final_size eigenpairs each
/// @param initial source vertex -> target vertex (0-based), one per source vertex
/// @return C, final_size x final_size
/// @throws UsageError if the sizes do not fit or an id is out of range
Eigen::MatrixXd zoomout_functional_map(const LaplaceBeltramiBasis& source,
                                       const LaplaceBeltramiBasis& target,
                                       const Eigen::VectorXi& initial,
                                       const ZoomOutOptions& options = {});

/// The pointwise map of a functional map C (k x k): for each of `rows` (source
/// vertices; empty: every vertex) the target vertex whose embedding
/// Phi_t(j, :k) C^T is nearest to Phi_s(i, :k).
/// @throws UsageError if C is larger than a basis or a row is out of range
Eigen::VectorXi pointwise_map(const LaplaceBeltramiBasis& source,
                              const LaplaceBeltramiBasis& target, const Eigen::MatrixXd& C,
                              const std::vector<int>& rows = {});

/// The refined map, one target vertex per source vertex: pointwise_map of
/// zoomout_functional_map on every source vertex.
/// @throws as zoomout_functional_map
Eigen::VectorXi zoomout(const LaplaceBeltramiBasis& source, const LaplaceBeltramiBasis& target,
                        const Eigen::VectorXi& initial, const ZoomOutOptions& options = {});

}  // namespace unfold
