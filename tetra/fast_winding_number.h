// Generalized winding number of a triangle soup (Jacobson et al. 2013): the
// solid angle the triangles subtend at a query point over 4 pi. It is 1 inside
// a closed outward-oriented surface, 0 outside, and degrades gracefully on
// self-intersections, small holes and non-manifold spots, which is why the
// robust tetrahedralization route uses it to decide what is inside.
// The fast evaluation follows Barill et al. 2018 ("Fast Winding Numbers for
// Soups and Clouds"): a bounding volume hierarchy over the triangles whose far
// clusters are replaced by their dipole (first-order) term; near clusters are
// summed exactly.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace unfold {

struct FastWindingNumberTree {
  struct Node {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();       ///< area-weighted triangle centroid
    Eigen::Vector3d area_normal = Eigen::Vector3d::Zero();  ///< sum of area-weighted normals
    double radius = 0;  ///< largest distance from center to a triangle corner below
    int first = 0;      ///< triangles order[first, first + count)
    int count = 0;
    int left = -1;        ///< children (-1 for a leaf); right = left + 1
    int first_point = 0;  ///< leaf: its distinct corners are points[first_point, + num_points)
    int num_points = 0;
  };
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  std::vector<int> order;  ///< triangle indices, grouped by node
  std::vector<Node> nodes;
  /// The nodes' far-field data in float, 32 bytes a node (Node has 80): the
  /// coarse pass's walk is bound by loading nodes, so it reads these. Centers
  /// are relative to float_origin (the box's center), so that float rounds them
  /// to the shape's size, not to its distance from the origin.
  struct FloatNode {
    float center[3];
    float area_normal[3];
    float radius;
    int left;
  };
  std::vector<FloatNode> float_nodes;
  Eigen::Vector3d float_origin = Eigen::Vector3d::Zero();
  /// The leaves' distinct corner positions, leaf after leaf: a query near a
  /// leaf takes each corner's offset and length once, not once per triangle.
  std::vector<Eigen::Vector3d> points;
  /// Per triangle order[k], its corners as indices into its leaf's points (3 per k).
  std::vector<unsigned char> corners;
  double accuracy = 2;  ///< clusters farther than accuracy * radius use the dipole term
};

/// Builds the hierarchy over the triangles F of V.
/// @param accuracy the far-field ratio beta (> 1): larger is slower and more accurate
FastWindingNumberTree fast_winding_number_precomputation(const Eigen::MatrixX3d& V,
                                                         const Eigen::MatrixX3i& F,
                                                         double accuracy = 2.0);

/// Approximate winding numbers at the rows of Q (parallel over the queries):
/// clusters farther than tree.accuracy times their radius by their dipole, the
/// near triangles' solid angles with fast_atan2 (each within kFastAtan2Error).
Eigen::VectorXd fast_winding_number_solve(const FastWindingNumberTree& tree,
                                          const Eigen::MatrixX3d& Q);

/// The winding number above which a point is inside (what classify decides).
inline constexpr double kInsideWinding = 0.5;

struct ClassifyOptions {
  double coarse_accuracy = 1.5;  ///< far-field ratio of the first pass (cheaper than the tree's)
  double margin = 0.3;           ///< |w| within this of 1/2: evaluated again at the tree's accuracy
};

/// Winding numbers for telling inside (|w| > 1/2) from outside, in about 0.4
/// of the time of fast_winding_number_solve: every query first with the coarser
/// far field, in float, then those whose |w| is within `margin` of 1/2, or whose
/// float value is in doubt (a hair's breadth off a triangle), again at the
/// tree's accuracy in double. Elsewhere the coarse value is kept: it differs from the
/// tree-accuracy one by at most 0.205 over the 15.4 million queries the
/// default's carves make on ../shared/data's 22 shapes and faust_remeshed
/// (docs/history/performance.md), so it is on the same side of 1/2, and within
/// `margin` of the tree-accuracy value (the robust route's rescue counts on both).
Eigen::VectorXd fast_winding_number_classify(const FastWindingNumberTree& tree,
                                             const Eigen::MatrixX3d& Q,
                                             const ClassifyOptions& options = {});

/// Whether fast_winding_number_classify evaluates a coarse value w again at the
/// tree's accuracy (|w| within `margin` of 1/2): its values in that band are
/// the accurate ones, the others within `margin` of them.
inline bool classify_refines(double w, const ClassifyOptions& options = {}) {
  return std::abs(std::abs(w) - kInsideWinding) < options.margin;
}

/// Exact winding numbers at the rows of Q (sum over every triangle), for checks.
Eigen::VectorXd winding_number(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                               const Eigen::MatrixX3d& Q);

}  // namespace unfold
