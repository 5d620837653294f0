#include "stages/lsmds_cascade.h"

#include "metrics/edge_ratio.h"

namespace unfold {

CascadeResult lsmds_cascade(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                            const LsmdsOptions& options) {
  CascadeResult c;
  const LsmdsResult lsmds_result =
      lsmds(graph, P, options, [&](int k, const Eigen::MatrixX3d& X, double stress) {
        c.history.push_back({k, 1, 0.0, stress, edge_ratio(graph, P, X)});
      });
  c.positions = lsmds_result.positions;
  c.iterations = lsmds_result.iterations;
  c.cascades = 1;
  c.final_energy = lsmds_result.stress.back();
  c.edge_ratio = edge_ratio(graph, P, c.positions);
  c.reached_band = true;  // no band applies
  return c;
}

}  // namespace unfold
