#include "mesh/sort_interior_vertices.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

// The low 21 bits of x spread to every third bit.
uint64_t spread_bits(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

}  // namespace

void sort_interior_vertices(TetMesh* tets, Eigen::MatrixX3d* made) {
  const int n = int(tets->V.rows()), first = tets->num_surface_vertices;
  if (made && made->rows() != n)
    throw UsageError("sort_interior_vertices: " + std::to_string(made->rows()) +
                     " made positions for " + std::to_string(n) + " vertices");
  if (n - first < 2) return;
  const Eigen::MatrixX3d& P = made ? *made : tets->V;
  const Eigen::RowVector3d low = P.colwise().minCoeff();
  const double extent = (P.colwise().maxCoeff() - low).maxCoeff();
  if (!(extent > 0)) return;
  const double scale = double((1 << 21) - 1) / extent;
  std::vector<std::pair<uint64_t, int>> keys;
  keys.reserve(size_t(n - first));
  for (int i = first; i < n; ++i) {
    uint64_t key = 0;
    for (int k = 0; k < 3; ++k) key |= spread_bits(uint64_t((P(i, k) - low[k]) * scale)) << k;
    keys.emplace_back(key, i);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> new_index(static_cast<size_t>(n));
  for (int i = 0; i < first; ++i) new_index[size_t(i)] = i;
  const auto renumbered = [&](const Eigen::MatrixX3d& X) {
    Eigen::MatrixX3d Y(n, 3);
    Y.topRows(first) = X.topRows(first);
    for (size_t k = 0; k < keys.size(); ++k) Y.row(first + int(k)) = X.row(keys[k].second);
    return Y;
  };
  for (size_t k = 0; k < keys.size(); ++k) new_index[size_t(keys[k].second)] = first + int(k);
  tets->V = renumbered(tets->V);
  if (made) *made = renumbered(*made);
  for (Eigen::Index t = 0; t < tets->T.rows(); ++t)
    for (int c = 0; c < 4; ++c) tets->T(t, c) = new_index[size_t(tets->T(t, c))];
}

}  // namespace unfold
