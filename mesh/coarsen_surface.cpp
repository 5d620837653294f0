#include "mesh/coarsen_surface.h"

#include <string>

#include "core/errors.h"
#include "mesh/lumped_masses.h"

namespace unfold {
namespace {

// Clusters of radius `hops` grown in vertex order; returns their count.
int grow_clusters(const EdgeGraph& graph, int hops, std::vector<int>* cluster_of) {
  const int n = graph.num_vertices;
  cluster_of->assign(size_t(n), -1);
  std::vector<int> depth(size_t(n), 0), front;
  int clusters = 0;
  for (int seed = 0; seed < n; ++seed) {
    if ((*cluster_of)[size_t(seed)] >= 0) continue;
    (*cluster_of)[size_t(seed)] = clusters;
    depth[size_t(seed)] = 0;
    front.assign(1, seed);
    for (size_t k = 0; k < front.size(); ++k) {  // breadth first: each vertex at its depth
      const int i = front[k];
      if (depth[size_t(i)] == hops) continue;
      for (int m = graph.offsets[size_t(i)]; m < graph.offsets[size_t(i) + 1]; ++m) {
        const int j = graph.neighbors[size_t(m)];
        if ((*cluster_of)[size_t(j)] >= 0) continue;
        (*cluster_of)[size_t(j)] = clusters;
        depth[size_t(j)] = depth[size_t(i)] + 1;
        front.push_back(j);
      }
    }
    ++clusters;
  }
  return clusters;
}

}  // namespace

SurfaceCoarsening coarsen_surface(const SurfaceMesh& surface, int hops) {
  if (hops < 1)
    throw UsageError("coarsen_surface: clusters of " + std::to_string(hops) +
                     " edges across (must be at least 1)");
  const int n = int(surface.V.rows());
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  const EdgeGraph fine = build_edge_graph(n, Eigen::MatrixXi(F));
  const Eigen::VectorXd area = lumped_masses(surface.V, F);
  SurfaceCoarsening c;
  const int count = grow_clusters(fine, hops, &c.cluster_of);
  c.V = Eigen::MatrixX3d::Zero(count, 3);
  c.masses = Eigen::VectorXd::Zero(count);
  for (int i = 0; i < n; ++i) {
    const int k = c.cluster_of[size_t(i)];
    c.V.row(k) += area[i] * surface.V.row(i);
    c.masses[k] += area[i];
  }
  c.V.array().colwise() /= c.masses.array();
  std::vector<Eigen::Vector2i> pairs;
  for (int e = 0; e < fine.num_edges(); ++e) {
    const int a = c.cluster_of[size_t(fine.edges(e, 0))],
              b = c.cluster_of[size_t(fine.edges(e, 1))];
    if (a != b) pairs.emplace_back(a, b);
  }
  Eigen::MatrixXi elements(Eigen::Index(pairs.size()), 2);
  for (size_t k = 0; k < pairs.size(); ++k) elements.row(Eigen::Index(k)) = pairs[k].transpose();
  c.graph = build_edge_graph(count, elements);
  return c;
}

}  // namespace unfold
