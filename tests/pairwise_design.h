// A covering design for option-matrix tests: rows of factor levels in which
// every pair of levels of every two factors occurs at least once, far fewer
// rows than the full Cartesian product.
#pragma once

#include <cstddef>
#include <set>
#include <tuple>
#include <vector>

namespace unfold::test {

/// One row: a level index per factor.
using DesignRow = std::vector<int>;

/// Level i of factor a together with level j of factor b, a < b.
using LevelPair = std::tuple<int, int, int, int>;

inline LevelPair level_pair(int a, int i, int b, int j) {
  return a < b ? LevelPair{a, i, b, j} : LevelPair{b, j, a, i};
}

/// The level pairs that `rows` do not cover.
/// @param levels number of levels of each factor
inline std::set<LevelPair> uncovered_pairs(const std::vector<int>& levels,
                                           const std::vector<DesignRow>& rows) {
  std::set<LevelPair> pairs;
  const size_t n = levels.size();
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b)
      for (int i = 0; i < levels[a]; ++i)
        for (int j = 0; j < levels[b]; ++j) pairs.insert(level_pair(int(a), i, int(b), j));
  for (const auto& row : rows)
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b) pairs.erase(level_pair(int(a), row[a], int(b), row[b]));
  return pairs;
}

/// Greedy pairwise design (deterministic): each row starts from the first
/// uncovered pair, then gives every other factor, in order, the level that
/// covers most uncovered pairs with the factors set so far.
/// @param levels number of levels of each factor (each >= 1)
inline std::vector<DesignRow> pairwise_design(const std::vector<int>& levels) {
  const size_t n = levels.size();
  std::vector<DesignRow> rows;
  for (auto todo = uncovered_pairs(levels, rows); !todo.empty();
       todo = uncovered_pairs(levels, rows)) {
    const auto [a, i, b, j] = *todo.begin();
    DesignRow row(n, -1);
    row[size_t(a)] = i;
    row[size_t(b)] = j;
    for (size_t f = 0; f < n; ++f) {
      if (row[f] >= 0) continue;
      int best = 0, best_gain = -1;
      for (int level = 0; level < levels[f]; ++level) {
        int gain = 0;
        for (size_t g = 0; g < n; ++g)
          if (row[g] >= 0) gain += int(todo.count(level_pair(int(f), level, int(g), row[g])));
        if (gain > best_gain) best = level, best_gain = gain;
      }
      row[f] = best;
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace unfold::test
