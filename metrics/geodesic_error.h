// E_geo (paper Eq. 10): how well Euclidean distances of the deformed shape
// match geodesic distances of the rest shape, both normalised.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

struct GeodesicErrorOptions {
  int exact_limit = 3000;  ///< all n sources when n <= this, else `sources` landmarks
  int sources = 256;       ///< landmark rows of the estimate
  uint64_t seed = 1;       ///< seed of the landmark choice (fixed: reproducible)
};

struct GeodesicError {
  double value = 0;           ///< E_geo (or its estimate)
  bool exact = false;         ///< true: every vertex was a source
  int sources_used = 0;       ///< rows of D' and G used
  double standard_error = 0;  ///< delete-one jackknife over the sources; 0 when exact
};

/// E_geo = || D'/||D'||_F - G/||G||_F ||_F with D'_ij = |q_i - q_j| and G_ij the
/// shortest-path distance from i to j in `graph` with edge lengths from P
/// (graph_geodesics()). Exact over all rows when n <= exact_limit; otherwise the
/// same formula over the rows of `sources` distinct vertices drawn uniformly
/// at random with a fixed seed (a row sample scales both norms alike, so the
/// normalisation cancels it), with its jackknife standard error. Parallel over sources,
/// deterministic. Invariant to rigid motions and uniform scaling of Q. Accurate to about 1e-8 near
/// 0 (computed as sqrt(2 - 2 <D', G> / (|D'| |G|))).
/// @param P rest positions (n x 3), n >= 2, graph connected
/// @param Q deformed positions (n x 3)
/// @throws UsageError on mismatched sizes, n < 2, exact_limit < 0 or sources < 1
/// @throws InputError if the graph is disconnected or all points coincide
GeodesicError geodesic_error(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q, const GeodesicErrorOptions& options = {});

/// E_geo over a surface alone: geodesic_error on the edge graph of the faces F,
/// the rest surface V against the deformed one Q.
/// @param F faces (polygons split into triangles, or triangles), indices into V
/// @return NaN when the faces' edges do not join every vertex
/// @throws as geodesic_error (UsageError on mismatched sizes)
GeodesicError surface_geodesic_error(const Eigen::MatrixX3d& V, const Eigen::MatrixXi& F,
                                     const Eigen::MatrixX3d& Q,
                                     const GeodesicErrorOptions& options = {});

/// The part of E_geo that depends on the rest shape alone: the sources (the
/// same as geodesic_error's) and their rows of G, kept in memory (sources x n
/// doubles). A caller can compute it while the solve runs (the pipeline does
/// for small meshes, whose solve runs on one thread), then finish with
/// geodesic_error_solve; the result is geodesic_error's, bit for bit.
struct GeodesicRows {
  std::vector<int> sources;
  /// row s: the graph distances from sources[s] to every vertex
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> G;
  bool exact = false;
};

/// @throws as geodesic_error (UsageError, InputError for a disconnected graph)
GeodesicRows geodesic_error_precomputation(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                           const GeodesicErrorOptions& options = {});

/// @param Q deformed positions, one row per column of rows.G
/// @throws UsageError on a size mismatch, InputError if all points coincide
GeodesicError geodesic_error_solve(const GeodesicRows& rows, const Eigen::MatrixX3d& Q);

/// surface_geodesic_error's rows of the rest surface (geodesic_error_precomputation on
/// the faces' edge graph), for surface_geodesic_error_solve with the deformed surface:
/// the same value, bit for bit.
/// @return no sources when the faces' edges do not join every vertex (E_geo over the
///         surface is then NaN)
GeodesicRows surface_geodesic_error_precomputation(const Eigen::MatrixX3d& V,
                                                   const Eigen::MatrixXi& F,
                                                   const GeodesicErrorOptions& options = {});

/// surface_geodesic_error from its rows: NaN where they have no sources.
/// @throws as geodesic_error_solve (UsageError on a size mismatch)
GeodesicError surface_geodesic_error_solve(const GeodesicRows& rows, const Eigen::MatrixX3d& Q);

}  // namespace unfold
