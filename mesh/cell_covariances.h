// The covariances of the cells of an edge graph (cell i: vertex i and its
// neighbours) between rest and current edges,
//   S_i = sum_{j in N_i} w_ij (p_i - p_j)(q_i - q_j)^T,
// whose best rotations (geometry/best_rotation.h) are the R_i of the rigidity
// term (paper Eq. 2), and the rest edges turned by per-cell rotations (the
// positions that best fit the turned cells). The rest side is precomputed once
// per mesh, in the graph's CSR order, so that a sweep reads it instead of
// gathering from P.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/rotations.h"
#include "geometry/row_major.h"
#include "mesh/edge_graph.h"

namespace unfold {

struct CellRestEdges {
  RowMatrixX3d weighted_edges;           ///< per CSR entry k of cell i: w_ij (p_i - p_j)
  RowMatrixX3d weighted_laplacian_rest;  ///< (L_w P)_i = sum_j w_ij (p_i - p_j)
  double weighted_squared_length = 0;    ///< sum_i sum_j w_ij |p_i - p_j|^2
};

/// The weighted rest edges of every cell.
/// @param rest         rest positions P (n x 3)
/// @param edge_weights w_ij per graph edge
/// @pre edge_weights has graph.num_edges() entries
CellRestEdges cell_rest_edges(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                              const std::vector<double>& edge_weights);

/// Adds scale * S_i into (*S)[i] for every cell, in parallel over cells.
/// @param Q current positions (n x 3)
/// @pre S holds n matrices
void add_cell_covariances(const EdgeGraph& graph, const CellRestEdges& rest,
                          const Eigen::MatrixX3d& Q, double scale, std::vector<Eigen::Matrix3d>* S);

/// Adds scale * B_i into row i of *B for every cell, in parallel over cells:
///   B_i = sum_{j in N_i} w_ij (R_i + R_j)(p_i - p_j),
/// the rest edges turned by the cells' rotations: the linear part of the
/// rigidity term (docs/method.md), and with L_w the right side of the
/// positions whose edges best match them (L_w Q = B / 2, up to a translation).
/// @pre R holds n rotations; B is n x 3
void add_rotated_rest_edges(const EdgeGraph& graph, const CellRestEdges& rest, const Rotations& R,
                            double scale, Eigen::MatrixX3d* B);

}  // namespace unfold
