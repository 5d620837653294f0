#include "solvers/scf.h"

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "geometry/best_rotation.h"
#include "solvers/arap_solve.h"

namespace unfold {
namespace {

// One rotation per node: the root's best fits the whole rest skeleton onto
// the straightened one; every other node's is its parent's followed by the
// least rotation that turns the bone (parent, node) into its new direction,
// so no bone twists about itself (the skeleton cannot tell a twist).
std::vector<Eigen::Matrix3d> node_rotations(const Eigen::MatrixX3d& X, const UnbentSkeleton& u) {
  const Eigen::MatrixX3d Xc = X.rowwise() - X.colwise().mean();
  const Eigen::MatrixX3d Yc = u.nodes.rowwise() - u.nodes.colwise().mean();
  std::vector<Eigen::Matrix3d> R(size_t(X.rows()));
  R[size_t(u.order[0])] = best_rotation(Xc.transpose() * Yc);
  for (size_t k = 1; k < u.order.size(); ++k) {
    const int c = u.order[k], p = u.parent[size_t(c)];
    const Eigen::Vector3d rest = R[size_t(p)] * (X.row(c) - X.row(p)).transpose();
    const Eigen::Vector3d now = (u.nodes.row(c) - u.nodes.row(p)).transpose();
    R[size_t(c)] = rest.norm() > 0 && now.norm() > 0
                       ? Eigen::Quaterniond::FromTwoVectors(rest, now).toRotationMatrix() *
                             R[size_t(p)]
                       : R[size_t(p)];
  }
  return R;
}

// The skeleton node of every graph vertex: the surface's from the contraction,
// an interior vertex's the nearest node.
Eigen::VectorXi nodes_of_vertices(const Eigen::MatrixX3d& P, const CurveSkeleton& s) {
  const int ns = int(s.node_of_vertex.size());
  Eigen::VectorXi node(P.rows());
  node.head(ns) = s.node_of_vertex;
  for (int i = ns; i < P.rows(); ++i)
    (s.nodes.rowwise() - P.row(i)).rowwise().squaredNorm().minCoeff(&node(i));
  return node;
}

}  // namespace

void validate_scf_options(const ScfOptions& o) {
  validate_curve_skeleton_options(o.skeleton);
  if (o.mds_iterations < 1) throw UsageError("config key 'scf.mds_iterations' must be >= 1");
  if (!(std::isfinite(o.blend_radius) && o.blend_radius > 0))
    throw UsageError("config key 'scf.blend_radius' must be a positive finite number");
  if (!(std::isfinite(o.arap_anchor) && o.arap_anchor > 0))
    throw UsageError("config key 'scf.arap_anchor' must be a positive finite number");
  if (o.arap_iterations < 0) throw UsageError("config key 'scf.arap_iterations' must be >= 0");
}

ScfResult scf(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int num_surface_vertices,
              const Eigen::MatrixX3i& F, const ScfOptions& options) {
  validate_scf_options(options);
  if (P.rows() != graph.num_vertices || num_surface_vertices < 1 ||
      num_surface_vertices > P.rows())
    throw UsageError("scf: positions, edge graph and surface vertex count do not match");
  const Eigen::MatrixX3d surface = P.topRows(num_surface_vertices);
  ScfResult r;
  r.skeleton = curve_skeleton(surface, F, options.skeleton);
  r.unbent = unbend_skeleton(r.skeleton.nodes, r.skeleton.edges, options.mds_iterations);
  const Eigen::MatrixX3d& X = r.skeleton.nodes;
  const Eigen::MatrixX3d& Y = r.unbent.nodes;
  const std::vector<Eigen::Matrix3d> R = node_rotations(X, r.unbent);

  // Skinning weights per node: (1 - (d/h)^2)^2 over the nodes within h along the skeleton.
  const int m = int(X.rows());
  const double diameter =
      2 * (surface.rowwise() - surface.colwise().mean()).rowwise().norm().maxCoeff();
  const double h = options.blend_radius * diameter;
  std::vector<std::vector<std::pair<int, double>>> weights(size_t(m));
  for (int s = 0; s < m; ++s)
    for (int k = 0; k < m; ++k) {
      const double t = r.unbent.distances(s, k) / h;
      if (t < 1) weights[size_t(s)].emplace_back(k, (1 - t * t) * (1 - t * t));
    }
  const Eigen::VectorXi node = nodes_of_vertices(P, r.skeleton);
  r.skinned.resize(P.rows(), 3);
  for (int i = 0; i < P.rows(); ++i) {
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    double total = 0;
    for (const auto& [k, w] : weights[size_t(node(i))]) {
      q += w * (Y.row(k).transpose() + R[size_t(k)] * (P.row(i) - X.row(k)).transpose());
      total += w;
    }
    r.skinned.row(i) = q.transpose() / total;
  }
  const Eigen::RowVector3d skinned_mean = r.skinned.colwise().mean();
  r.skinned.rowwise() -= skinned_mean;

  ArapSolveOptions refine;
  refine.num_fixed = 1;  // vertex 0 held where skinning put it; the anchor holds the rest
  refine.anchor = options.arap_anchor;
  refine.max_iterations = options.arap_iterations;
  r.positions = arap_solve(graph, P, r.skinned, refine);
  const Eigen::RowVector3d refined_mean = r.positions.colwise().mean();
  r.positions.rowwise() -= refined_mean;
  r.canonical_nodes = Y.rowwise() - (skinned_mean + refined_mean);
  if (!r.positions.allFinite()) throw NumericalError("scf: the deformation produced NaN");
  LOG(INFO) << "scf: " << m << " skeleton nodes, skeleton MDS stress " << r.unbent.stress
            << " after " << r.unbent.iterations << " transforms";
  return r;
}

}  // namespace unfold
