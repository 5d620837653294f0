// Nearest-neighbour queries among 3D points: a k-d tree, built once, queried
// many times (ICP, map extraction between canonical forms).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// A static k-d tree over the rows of a point matrix (the tree keeps a copy).
class PointTree {
 public:
  /// @param points n x 3, n >= 1, finite
  /// @throws UsageError for no points or a non-finite coordinate
  explicit PointTree(const Eigen::MatrixX3d& points);

  /// The row of the points nearest to q (the lowest row among equally near ones
  /// is not guaranteed), and its squared distance in *squared_distance if given.
  int nearest(const Eigen::Vector3d& q, double* squared_distance = nullptr) const;

  /// nearest() of every row of Q (in parallel for many rows); squared distances in
  /// *squared if given.
  Eigen::VectorXi nearest_rows(const Eigen::MatrixX3d& Q, Eigen::VectorXd* squared = nullptr) const;

  int size() const { return int(points_.rows()); }

 private:
  struct Node {
    int begin, end;  ///< range of order_ (a leaf when children are -1)
    int left = -1, right = -1;
    int axis = 0;
    double split = 0;
  };
  int build(int begin, int end);
  void search(int node, const Eigen::Vector3d& q, int* best, double* best_d2) const;

  Eigen::MatrixX3d points_;
  std::vector<int> order_;
  std::vector<Eigen::Vector3d> sorted_;  ///< points_ in order_'s order: leaves read contiguously
  std::vector<Node> nodes_;
};

}  // namespace unfold
