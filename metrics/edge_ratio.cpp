#include "metrics/edge_ratio.h"

#include <algorithm>
#include <string>

#include "core/chunked_row_sum.h"
#include "core/errors.h"

namespace unfold {
namespace {

double ratio(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q, int i, int j) {
  const double rest = (P.row(i) - P.row(j)).norm();
  if (rest == 0)
    throw InputError("edge_ratio: edge " + std::to_string(std::min(i, j)) + "-" +
                     std::to_string(std::max(i, j)) + " has zero rest length");
  return (Q.row(i) - Q.row(j)).norm() / rest;
}

void check_sizes(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q) {
  if (P.rows() != graph.num_vertices || Q.rows() != graph.num_vertices)
    throw UsageError("edge_ratio: need P and Q with one row per graph vertex");
}

}  // namespace

double edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q) {
  check_sizes(graph, P, Q);
  if (graph.num_edges() == 0) throw InputError("edge_ratio: the graph has no edges");
  double sum = 0;
  for (int e = 0; e < graph.num_edges(); ++e)
    sum += ratio(P, Q, graph.edges(e, 0), graph.edges(e, 1));
  return sum / graph.num_edges();
}

Eigen::VectorXd edge_lengths(const EdgeGraph& graph, const Eigen::MatrixX3d& P) {
  check_sizes(graph, P, P);
  Eigen::VectorXd lengths(graph.num_edges());
  for (int e = 0; e < graph.num_edges(); ++e) {
    lengths[e] = (P.row(graph.edges(e, 0)) - P.row(graph.edges(e, 1))).norm();
    if (lengths[e] == 0) ratio(P, P, graph.edges(e, 0), graph.edges(e, 1));  // throws, naming it
  }
  return lengths;
}

double edge_ratio(const EdgeGraph& graph, const Eigen::VectorXd& rest_lengths,
                  const Eigen::MatrixX3d& Q) {
  if (rest_lengths.size() != graph.num_edges() || Q.rows() != graph.num_vertices)
    throw UsageError("edge_ratio: need one rest length per edge and one row of Q per vertex");
  if (graph.num_edges() == 0) throw InputError("edge_ratio: the graph has no edges");
  // Once per solver iteration: on all threads.
  const auto sum = chunked_row_sum(graph.num_edges(), [&](int e) {
    return Eigen::Array<double, 1, 1>((Q.row(graph.edges(e, 0)) - Q.row(graph.edges(e, 1))).norm() /
                                      rest_lengths[e]);
  });
  return sum(0) / graph.num_edges();
}

Eigen::VectorXd vertex_edge_ratio(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                  const Eigen::MatrixX3d& Q) {
  check_sizes(graph, P, Q);
  Eigen::VectorXd result = Eigen::VectorXd::Ones(graph.num_vertices);
  for (int i = 0; i < graph.num_vertices; ++i) {
    if (graph.degree(i) == 0) continue;
    double sum = 0;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      sum += ratio(P, Q, i, graph.neighbors[size_t(k)]);
    result[i] = sum / graph.degree(i);
  }
  return result;
}

}  // namespace unfold
