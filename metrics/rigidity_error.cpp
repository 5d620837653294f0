#include "metrics/rigidity_error.h"

#include <Eigen/Geometry>
#include <string>

#include "core/errors.h"
#include "mesh/best_rotations.h"

namespace unfold {

RigidityError rigidity_error(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q) {
  const int n = graph.num_vertices;
  if (n == 0 || P.rows() != n || Q.rows() != n)
    throw UsageError("rigidity_error: need P and Q with one row per graph vertex, n > 0");
  for (int e = 0; e < graph.num_edges(); ++e)
    if (P.row(graph.edges(e, 0)) == P.row(graph.edges(e, 1)))
      throw InputError("rigidity_error: edge " + std::to_string(graph.edges(e, 0)) + "-" +
                       std::to_string(graph.edges(e, 1)) + " has zero rest length");
  Rotations R;
  best_rotations(graph, P, Q, &R);
  RigidityError result;
  result.per_vertex.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    double sum = 0;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const Eigen::Vector3d p = (P.row(i) - P.row(j)).transpose();
      const Eigen::Vector3d q = (Q.row(i) - Q.row(j)).transpose();
      sum += (q - R[size_t(i)] * p).norm() / p.norm();
    }
    result.per_vertex[i] = sum;
  }
  result.mean = result.per_vertex.sum() / n;  // serial sum: independent of thread count
  return result;
}

}  // namespace unfold
