#include "mesh/best_rotations.h"

#include "core/parallel.h"
#include "geometry/best_rotation.h"
#include "mesh/cell_covariances.h"

namespace unfold {

void best_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                    const Eigen::MatrixX3d& current, Rotations* R) {
  const int n = graph.num_vertices;
  std::vector<Eigen::Matrix3d> S(size_t(n), Eigen::Matrix3d::Zero());
  add_cell_covariances(
      graph, cell_rest_edges(graph, rest, std::vector<double>(size_t(graph.num_edges()), 1.0)),
      current, 1.0, &S);
  R->resize(size_t(n));
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int i = 0; i < n; ++i)
    (*R)[size_t(i)] =
        graph.degree(i) > 0 ? best_rotation(S[size_t(i)]) : Eigen::Matrix3d::Identity();
}

}  // namespace unfold
