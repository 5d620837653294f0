// The edge graph of a tetrahedral (or triangle) mesh: the cells N_i of the
// paper are the neighbour lists of this graph.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace unfold {

struct EdgeGraph {
  int num_vertices = 0;
  Eigen::MatrixX2i edges;          ///< undirected edges, edges(e,0) < edges(e,1), sorted
  std::vector<int> offsets;        ///< CSR: neighbours of i are [offsets[i], offsets[i+1])
  std::vector<int> neighbors;      ///< CSR neighbour vertex indices, ascending per vertex
  std::vector<int> neighbor_edge;  ///< CSR: index into `edges` of each neighbour entry

  int degree(int i) const { return offsets[i + 1] - offsets[i]; }
  int num_edges() const { return int(edges.rows()); }
};

/// Builds the edge graph from elements (rows of vertex indices: tets or triangles).
/// Every pair of vertices sharing an element becomes one edge.
/// @param num_vertices vertex count; isolated vertices get no neighbours.
/// @param elements     rows of k >= 2 vertex indices, each in [0, num_vertices).
EdgeGraph build_edge_graph(int num_vertices, const Eigen::MatrixXi& elements);

/// The edge graph of the given edges, which must be as EdgeGraph::edges holds
/// them: each row i < j, both in [0, num_vertices), rows sorted, none twice
/// (unchecked: the builders above make them so).
EdgeGraph edge_graph_from_sorted_edges(int num_vertices, Eigen::MatrixX2i edges);

/// Uniform-weight graph Laplacian L = D - A (n x n, symmetric, rows sum to zero).
Eigen::SparseMatrix<double> graph_laplacian(const EdgeGraph& graph);

/// Labels each vertex with its connected component (0-based); returns the count.
int connected_components(const EdgeGraph& graph, std::vector<int>* labels = nullptr);

}  // namespace unfold
