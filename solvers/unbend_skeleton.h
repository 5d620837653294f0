// SCF's second step (Pickup et al. 2016): the curve skeleton straightened by
// MDS on the distances along it, with every bone's length kept.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

struct UnbentSkeleton {
  Eigen::MatrixX3d nodes;     ///< straightened node positions
  Eigen::MatrixXd distances;  ///< all-pairs distances along the rest skeleton's bones
  std::vector<int> parent;    ///< spanning tree from the centre node: parent or -1 (root)
  std::vector<int> order;     ///< the nodes, parents before children
  double stress = 0;          ///< SMACOF's final stress (before the lengths are restored)
  int iterations = 0;         ///< Guttman transforms
};

/// Straightens a skeleton: SMACOF (all pairs, weights 1, started from the
/// nodes) on the graph geodesics of the skeleton, which a branched, bent
/// skeleton cannot keep and a straight one can; then, since MDS keeps bones
/// only in the least-squares sense, every bone of a breadth-first spanning
/// tree from the centre node (least eccentricity) gets back its rest length
/// along its MDS direction, parents first (bones closing a cycle keep their
/// MDS length). Equivariant under rigid motions of the nodes.
/// @param nodes          rest node positions
/// @param edges          bones: node index pairs
/// @param max_iterations Guttman transforms at most (>= 1)
/// @param tolerance      stop when the relative stress decrease is below this
/// @throws UsageError if an edge names a missing node, NumericalError if the
///         skeleton is disconnected
UnbentSkeleton unbend_skeleton(const Eigen::MatrixX3d& nodes, const Eigen::MatrixX2i& edges,
                               int max_iterations = 300, double tolerance = 1e-7);

}  // namespace unfold
