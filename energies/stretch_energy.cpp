#include "energies/stretch_energy.h"

#include "energies/jet_evaluation.h"
#include "energies/row_major.h"

namespace unfold {

double StretchEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& /*R*/, double scale,
                               Eigen::MatrixX3d* grad) const {
  const int n = graph_.num_vertices;
  const RowMatrixX3d q = Q;
  RowMatrixX3d g;
  if (grad) g.setZero(n, 3);
  auto at = [&](int v) { return grad ? g.data() + 3 * v : nullptr; };
  const StretchSpreadResidual spread(Q.colwise().mean().transpose(), n);
  double energy = 0;
  for (int i = 0; i < n; ++i) {
    const std::array<double*, 1> gi = {at(i)};
    energy -= squared_norm<3, 1>(spread, {q.row(i).data()}, -scale, grad ? &gi : nullptr);
  }
  const StretchEdgeResidual edge;
  for (int e = 0; e < graph_.num_edges(); ++e) {
    const int i = graph_.edges(e, 0), j = graph_.edges(e, 1);
    const std::array<double*, 2> gij = {at(i), at(j)};
    energy +=
        squared_norm<3, 2>(edge, {q.row(i).data(), q.row(j).data()}, scale, grad ? &gij : nullptr);
  }
  if (grad) *grad += g;
  return energy;
}

void StretchEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (int i = 0; i < graph_.num_vertices; ++i)
    H->emplace_back(i, i, scale * 2.0 * (graph_.degree(i) - graph_.num_vertices));
  for (int e = 0; e < graph_.num_edges(); ++e) {
    H->emplace_back(graph_.edges(e, 0), graph_.edges(e, 1), -2.0 * scale);
    H->emplace_back(graph_.edges(e, 1), graph_.edges(e, 0), -2.0 * scale);
  }
}

}  // namespace unfold
