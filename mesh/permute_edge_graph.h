// An edge graph with its vertices renumbered (mesh/locality_order.h): the same
// graph, its edges sorted again for the new numbers.
#pragma once

#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// The graph whose vertex `new` is g's vertex order[new].
/// @param g          an edge graph (build_edge_graph)
/// @param order      a permutation of 0..n-1, order[new] = old
/// @param edge_order optional: per edge of the result, the index of the same
///        edge in g (so that per-edge data follows: data[edge_order[e]])
/// @throws UsageError if order is not a permutation of g's vertices
EdgeGraph permute_edge_graph(const EdgeGraph& g, const std::vector<int>& order,
                             std::vector<int>* edge_order = nullptr);

}  // namespace unfold
