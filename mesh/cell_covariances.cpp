#include "mesh/cell_covariances.h"

#include "core/parallel.h"

namespace unfold {

CellRestEdges cell_rest_edges(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                              const std::vector<double>& edge_weights) {
  CellRestEdges cells;
  cells.weighted_edges.resize(Eigen::Index(graph.neighbors.size()), 3);
  cells.weighted_laplacian_rest = RowMatrixX3d::Zero(rest.rows(), 3);
  for (int i = 0; i < graph.num_vertices; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const double w = edge_weights[size_t(graph.neighbor_edge[size_t(k)])];
      const Eigen::RowVector3d edge = rest.row(i) - rest.row(graph.neighbors[size_t(k)]);
      cells.weighted_edges.row(k) = w * edge;
      cells.weighted_laplacian_rest.row(i) += cells.weighted_edges.row(k);
      cells.weighted_squared_length += cells.weighted_edges.row(k).dot(edge);
    }
  return cells;
}

void add_cell_covariances(const EdgeGraph& graph, const CellRestEdges& rest,
                          const Eigen::MatrixX3d& Q, double scale,
                          std::vector<Eigen::Matrix3d>* S) {
  const RowMatrixX3d q = Q;
#pragma omp parallel for schedule(static) if (graph.num_vertices >= kMinParallelRows)
  for (int i = 0; i < graph.num_vertices; ++i) {
    // sum_j w_ij e_ij (q_i - q_j)^T = (L_w P)_i q_i^T - sum_j w_ij e_ij q_j^T
    Eigen::Matrix3d s = rest.weighted_laplacian_rest.row(i).transpose() * q.row(i);
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      s.noalias() -= rest.weighted_edges.row(k).transpose() * q.row(graph.neighbors[size_t(k)]);
    (*S)[size_t(i)] += scale * s;
  }
}

void add_rotated_rest_edges(const EdgeGraph& graph, const CellRestEdges& rest, const Rotations& R,
                            double scale, Eigen::MatrixX3d* B) {
  // B_i = R_i (L_w P)_i + sum_j R_j w_ij (p_i - p_j).
#pragma omp parallel for schedule(static) if (graph.num_vertices >= kMinParallelRows)
  for (int i = 0; i < graph.num_vertices; ++i) {
    Eigen::Vector3d b = R[size_t(i)] * rest.weighted_laplacian_rest.row(i).transpose();
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      b.noalias() += R[size_t(graph.neighbors[size_t(k)])] * rest.weighted_edges.row(k).transpose();
    B->row(i) += scale * b.transpose();
  }
}

}  // namespace unfold
