// The oriented boundary of a triangle soup, as a chain of directed edges: what
// keeps its generalized winding number from being an integer off the surface.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

struct ChainEdge {
  int from = 0, to = 0;
  int multiplicity = 1;  ///< positive: from -> to this many times
};

/// The directed edges of F's triangles that their reverses do not cancel: each
/// edge {a, b} with (uses a -> b) - (uses b -> a) != 0, directed so that its
/// multiplicity is positive, ordered by (min(a, b), max(a, b)). Empty exactly
/// when the triangles form a closed, consistently oriented surface
/// (self-intersections and non-manifold edges allowed), whose winding number
/// is then an integer off the surface. A hole's rim appears once; a seam
/// between two patches oriented against each other, twice.
/// @param F triangles, vertex indices (non-negative)
std::vector<ChainEdge> boundary_chain(const Eigen::MatrixX3i& F);

}  // namespace unfold
