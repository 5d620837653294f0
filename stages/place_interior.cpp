#include "stages/place_interior.h"

#include <utility>

#include "solvers/arap_solve.h"

namespace unfold {

Eigen::MatrixX3d place_interior(const EdgeGraph& graph, const TetMesh& tets,
                                const Eigen::MatrixX3d& surface_positions) {
  const int num_surface = tets.num_surface_vertices;
  Eigen::MatrixX3d Q = tets.V.rowwise() - tets.V.colwise().mean();
  Q.topRows(num_surface) = surface_positions;
  ArapSolveOptions place;
  place.num_fixed = num_surface;
  return arap_solve(graph, tets.V, std::move(Q), place);
}

}  // namespace unfold
