// Disjoint sets of the integers [0, n) with path halving: which parts a set
// of links (tets, edges) joins.
#pragma once

#include <numeric>
#include <vector>

namespace unfold {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }
  /// The representative of i's set.
  int find(int i) {
    while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
    return i;
  }
  /// Joins a's and b's sets.
  void unite(int a, int b) { parent[size_t(find(a))] = find(b); }
};

}  // namespace unfold
