#include "mesh/sort_interior_vertices.h"

#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/locality_order.h"

namespace unfold {

void sort_interior_vertices(TetMesh* tets, Eigen::MatrixX3d* made) {
  const int n = int(tets->V.rows()), first = tets->num_surface_vertices;
  if (made && made->rows() != n)
    throw UsageError("sort_interior_vertices: " + std::to_string(made->rows()) +
                     " made positions for " + std::to_string(n) + " vertices");
  if (n - first < 2) return;
  const std::vector<int> order = locality_order(made ? *made : tets->V, first);
  std::vector<int> new_index(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) new_index[size_t(order[size_t(i)])] = i;
  tets->V = Eigen::MatrixX3d(tets->V(order, Eigen::all));
  if (made) *made = Eigen::MatrixX3d((*made)(order, Eigen::all));
  for (Eigen::Index t = 0; t < tets->T.rows(); ++t)
    for (int c = 0; c < 4; ++c) tets->T(t, c) = new_index[size_t(tets->T(t, c))];
}

}  // namespace unfold
