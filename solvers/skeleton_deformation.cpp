#include "solvers/skeleton_deformation.h"

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "geometry/best_rotation.h"
#include "solvers/arap_solve.h"

namespace unfold {
namespace {

std::vector<Eigen::Matrix3d> node_rotations(const Eigen::MatrixX3d& X, const UnbentSkeleton& u) {
  const Eigen::MatrixX3d Xc = X.rowwise() - X.colwise().mean();
  const Eigen::MatrixX3d Yc = u.nodes.rowwise() - u.nodes.colwise().mean();
  std::vector<Eigen::Matrix3d> R(size_t(X.rows()));
  R[size_t(u.order[0])] = best_rotation(Xc.transpose() * Yc);
  for (size_t k = 1; k < u.order.size(); ++k) {
    const int c = u.order[k], p = u.parent[size_t(c)];
    const Eigen::Vector3d rest = R[size_t(p)] * (X.row(c) - X.row(p)).transpose();
    const Eigen::Vector3d now = (u.nodes.row(c) - u.nodes.row(p)).transpose();
    R[size_t(c)] =
        rest.norm() > 0 && now.norm() > 0
            ? Eigen::Quaterniond::FromTwoVectors(rest, now).toRotationMatrix() * R[size_t(p)]
            : R[size_t(p)];
  }
  return R;
}

// The skeleton node of every graph vertex: the surface's from the contraction,
// an interior vertex's the nearest node.
Eigen::VectorXi nodes_of_vertices(const Eigen::MatrixX3d& P, const CurveSkeleton& s) {
  const Eigen::Index ns = s.node_of_vertex.size();
  Eigen::VectorXi node(P.rows());
  node.head(ns) = s.node_of_vertex;
  for (Eigen::Index i = ns; i < P.rows(); ++i)
    (s.nodes.rowwise() - P.row(i)).rowwise().squaredNorm().minCoeff(&node(i));
  return node;
}

}  // namespace

SkeletonDeformation deform_by_skeleton(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const CurveSkeleton& skeleton, const UnbentSkeleton& unbent,
                                       const SkeletonDeformationOptions& options) {
  const Eigen::MatrixX3d& X = skeleton.nodes;
  const Eigen::MatrixX3d& Y = unbent.nodes;
  const Eigen::Index m = X.rows();
  if (P.rows() != graph.num_vertices || skeleton.node_of_vertex.size() > P.rows() ||
      Y.rows() != m || unbent.distances.rows() != m || unbent.order.size() != size_t(m) ||
      (skeleton.node_of_vertex.size() > 0 &&
       (skeleton.node_of_vertex.minCoeff() < 0 || skeleton.node_of_vertex.maxCoeff() >= m)))
    throw UsageError("deform_by_skeleton: mesh, skeleton and moved skeleton do not match");
  if (!(std::isfinite(options.blend_radius) && options.blend_radius > 0))
    throw UsageError("deform_by_skeleton: the blend radius must be positive");
  const std::vector<Eigen::Matrix3d> R = node_rotations(X, unbent);

  std::vector<std::vector<std::pair<int, double>>> weights(static_cast<size_t>(m));
  for (Eigen::Index s = 0; s < m; ++s)
    for (Eigen::Index k = 0; k < m; ++k) {
      const double t = unbent.distances(s, k) / options.blend_radius;
      if (t < 1) weights[size_t(s)].emplace_back(int(k), (1 - t * t) * (1 - t * t));
    }
  const Eigen::VectorXi node = nodes_of_vertices(P, skeleton);
  SkeletonDeformation d;
  d.skinned.resize(P.rows(), 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    double total = 0;
    for (const auto& [k, w] : weights[size_t(node(i))]) {
      q += w * (Y.row(k).transpose() + R[size_t(k)] * (P.row(i) - X.row(k)).transpose());
      total += w;
    }
    d.skinned.row(i) = q.transpose() / total;
  }
  const Eigen::RowVector3d skinned_mean = d.skinned.colwise().mean();
  d.skinned.rowwise() -= skinned_mean;

  ArapSolveOptions refine;
  refine.num_fixed = 1;  // vertex 0 held where skinning put it; the anchor holds the rest
  refine.anchor = options.arap_anchor;
  refine.max_iterations = options.arap_iterations;
  d.positions = arap_solve(graph, P, d.skinned, refine);
  const Eigen::RowVector3d refined_mean = d.positions.colwise().mean();
  d.positions.rowwise() -= refined_mean;
  d.canonical_nodes = Y.rowwise() - (skinned_mean + refined_mean);
  if (!d.positions.allFinite()) throw NumericalError("scf: the deformation produced NaN");
  return d;
}

}  // namespace unfold
