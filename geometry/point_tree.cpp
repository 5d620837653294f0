#include "geometry/point_tree.h"

#include <algorithm>
#include <limits>

#include "core/errors.h"

namespace unfold {

namespace {
constexpr int kLeafSize = 12;
}

PointTree::PointTree(const Eigen::MatrixX3d& points) : points_(points) {
  if (points.rows() == 0) throw UsageError("PointTree: no points");
  if (!points.allFinite()) throw UsageError("PointTree: a point has a non-finite coordinate");
  order_.resize(points.rows());
  for (int i = 0; i < int(order_.size()); ++i) order_[i] = i;
  nodes_.reserve(2 * order_.size() / kLeafSize + 2);
  build(0, int(order_.size()));
  sorted_.resize(order_.size());
  for (size_t k = 0; k < order_.size(); ++k) sorted_[k] = points_.row(order_[k]).transpose();
}

int PointTree::build(int begin, int end) {
  const int id = int(nodes_.size());
  nodes_.push_back(Node{begin, end});
  if (end - begin <= kLeafSize) return id;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (int k = begin; k < end; ++k) {
    lo = lo.cwiseMin(points_.row(order_[k]).transpose());
    hi = hi.cwiseMax(points_.row(order_[k]).transpose());
  }
  int axis;
  (hi - lo).maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return points_(a, axis) < points_(b, axis); });
  const double split = points_(order_[mid], axis);
  const int left = build(begin, mid);
  const int right = build(mid, end);
  nodes_[id].axis = axis;
  nodes_[id].split = split;
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

void PointTree::search(int id, const Eigen::Vector3d& q, int* best, double* best_d2) const {
  const Node& node = nodes_[id];
  if (node.left < 0) {
    for (int k = node.begin; k < node.end; ++k) {
      const double d2 = (sorted_[size_t(k)] - q).squaredNorm();
      if (d2 < *best_d2) {
        *best_d2 = d2;
        *best = order_[size_t(k)];
      }
    }
    return;
  }
  const double offset = q(node.axis) - node.split;
  const int near = offset < 0 ? node.left : node.right;
  const int far = offset < 0 ? node.right : node.left;
  search(near, q, best, best_d2);
  if (offset * offset < *best_d2) search(far, q, best, best_d2);
}

int PointTree::nearest(const Eigen::Vector3d& q, double* squared_distance) const {
  int best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  search(0, q, &best, &best_d2);
  if (squared_distance) *squared_distance = best_d2;
  return best;
}

Eigen::VectorXi PointTree::nearest_rows(const Eigen::MatrixX3d& Q, Eigen::VectorXd* squared) const {
  Eigen::VectorXi ids(Q.rows());
  Eigen::VectorXd d2(Q.rows());
  // In parallel only when there is enough work to pay for waking threads
  // (ICP calls this many times with a few thousand points).
#pragma omp parallel for schedule(static) if (Q.rows() >= 50000)
  for (Eigen::Index i = 0; i < Q.rows(); ++i) ids(i) = nearest(Q.row(i).transpose(), &d2(i));
  if (squared) *squared = d2;
  return ids;
}

}  // namespace unfold
