#include "mesh/drop_inverted_tets.h"

#include <algorithm>
#include <vector>

#include "core/errors.h"
#include "core/union_find.h"
#include "mesh/tet_quality.h"
#include "mesh/tet_volumes.h"

namespace unfold {

DroppedTets drop_inverted_tets(const Eigen::MatrixX3d& made, const Eigen::MatrixX3d& rest,
                               Eigen::MatrixX4i* T, const Eigen::MatrixXi* joined,
                               double min_quality) {
  const int n = int(made.rows());
  if (rest.rows() != n)
    throw UsageError("drop_inverted_tets: the two positions have " + std::to_string(n) + " and " +
                     std::to_string(rest.rows()) + " rows");
  if (T->size() > 0 && (T->minCoeff() < 0 || T->maxCoeff() >= n))
    throw UsageError("drop_inverted_tets: a tet corner is not one of the " + std::to_string(n) +
                     " vertices");
  if (!(min_quality >= 0 && min_quality <= 1))
    throw UsageError("drop_inverted_tets: min_quality must be in [0, 1], got " +
                     std::to_string(min_quality));
  const Eigen::VectorXd before = tet_volumes(made, *T), after = tet_volumes(rest, *T);
  const Eigen::VectorXd quality =
      min_quality > 0 ? tet_quality(rest, *T) : Eigen::VectorXd::Ones(T->rows());
  std::vector<char> keep(size_t(T->rows()));
  UnionFind parts(n);
  if (joined)
    for (Eigen::Index r = 0; r < joined->rows(); ++r)
      for (Eigen::Index k = 1; k < joined->cols(); ++k)
        parts.unite((*joined)(r, 0), (*joined)(r, k));
  const auto inverted = [&](Eigen::Index t) { return before[t] * after[t] <= 0 && before[t] != 0; };
  for (Eigen::Index t = 0; t < T->rows(); ++t) {
    keep[size_t(t)] = !inverted(t) && quality[t] >= min_quality;
    if (keep[size_t(t)])
      for (int k = 1; k < 4; ++k) parts.unite((*T)(t, 0), (*T)(t, k));
  }
  // The upright first, then the least inverted (rest volume over made volume
  // largest): what must stay should be the tets nearest to having a rest shape.
  std::vector<Eigen::Index> dropped_rows;
  for (Eigen::Index t = 0; t < T->rows(); ++t)
    if (!keep[size_t(t)]) dropped_rows.push_back(t);
  const auto ratio = [&](Eigen::Index t) { return before[t] != 0 ? after[t] / before[t] : 0.0; };
  std::stable_sort(dropped_rows.begin(), dropped_rows.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return ratio(a) > ratio(b); });
  for (const Eigen::Index t : dropped_rows) {
    for (int k = 1; k < 4; ++k)
      if (parts.find((*T)(t, 0)) != parts.find((*T)(t, k))) keep[size_t(t)] = 1;
    if (keep[size_t(t)])
      for (int k = 1; k < 4; ++k) parts.unite((*T)(t, 0), (*T)(t, k));
  }
  DroppedTets out;
  Eigen::Index rows = 0;
  for (Eigen::Index t = 0; t < T->rows(); ++t) {
    if (keep[size_t(t)]) {
      out.kept_inverted += inverted(t);
      T->row(rows++) = T->row(t);
    } else {
      ++(inverted(t) ? out.inverted : out.flat);
    }
  }
  T->conservativeResize(rows, 4);
  return out;
}

}  // namespace unfold
