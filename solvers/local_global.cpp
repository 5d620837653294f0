#include "solvers/local_global.h"

#include "core/errors.h"

namespace unfold {

void local_global_precomputation(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                                 LocalGlobalData* data) {
  data->graph = &graph;
  data->rest = rest;
  data->L = graph_laplacian(graph);
  data->ldlt.analyzePattern(data->L);
  data->beta = 0;
}

void local_global_set_beta(double beta, LocalGlobalData* data) {
  Eigen::SparseMatrix<double> A = (beta + 1.0) * data->L;
  A.diagonal().array() -= double(data->graph->num_vertices);
  data->ldlt.factorize(A);
  if (data->ldlt.info() != Eigen::Success)
    throw NumericalError("factorizing the global matrix failed at beta = " + std::to_string(beta));
  data->beta = beta;
  data->negative_pivots = int((data->ldlt.vectorD().array() < 0).count());
}

void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q) {
  const EdgeGraph& g = *data.graph;
  const Eigen::MatrixX3d& P = data.rest;
  Eigen::MatrixX3d rhs(g.num_vertices, 3);
  const double half_beta = 0.5 * data.beta;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < g.num_vertices; ++i) {
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      b.noalias() += (R[size_t(i)] + R[size_t(j)]) * (P.row(i) - P.row(j)).transpose();
    }
    rhs.row(i) = half_beta * b.transpose();
  }
  *Q = data.ldlt.solve(rhs);
  // Roundoff leaves a tiny constant component; the energy ignores translation.
  Q->rowwise() -= Q->colwise().mean();
}

}  // namespace unfold
