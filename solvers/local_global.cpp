#include "solvers/local_global.h"

#include "core/errors.h"

namespace unfold {

void local_global_precomputation(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                                 LocalGlobalData* data) {
  data->graph = &graph;
  data->rest = rest;
  data->L = graph_laplacian(graph);
  data->LP = data->L * rest;
  data->A = data->L;
  data->ldlt.analyze(data->A);
  data->rhs.resize(graph.num_vertices, 3);
  data->beta = 0;
}

void local_global_set_beta(double beta, LocalGlobalData* data) {
  // A shares L's pattern, so only values change: (beta+1) L - n I in place.
  Eigen::Map<Eigen::VectorXd>(data->A.valuePtr(), data->A.nonZeros()) =
      (beta + 1.0) * Eigen::Map<const Eigen::VectorXd>(data->L.valuePtr(), data->L.nonZeros());
  data->A.diagonal().array() -= double(data->graph->num_vertices);
  try {
    data->ldlt.factorize(data->A);
  } catch (const NumericalError& e) {
    throw NumericalError("factorizing the global matrix failed at beta = " + std::to_string(beta) +
                         ": " + e.what());
  }
  data->beta = beta;
  data->negative_pivots = data->ldlt.negative_pivots();
}

void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q) {
  const EdgeGraph& g = *data.graph;
  const Eigen::MatrixX3d& P = data.rest;
  Eigen::MatrixX3d& rhs = data.rhs;
  const double half_beta = 0.5 * data.beta;
  // b_i = sum_j (R_i + R_j)(p_i - p_j) = R_i (L P)_i + sum_j R_j (p_i - p_j).
#pragma omp parallel for schedule(static)
  for (int i = 0; i < g.num_vertices; ++i) {
    const Eigen::Vector3d p = P.row(i).transpose();
    Eigen::Vector3d b = R[size_t(i)] * data.LP.row(i).transpose();
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      b.noalias() += R[size_t(j)] * (p - P.row(j).transpose());
    }
    rhs.row(i) = half_beta * b.transpose();
  }
  data.ldlt.solve(rhs, Q);
  // Roundoff leaves a tiny constant component; the energy ignores translation.
  Q->rowwise() -= Q->colwise().mean();
}

}  // namespace unfold
