#include "pipeline/tet_fields.h"

#include <cmath>

#include "mesh/edge_graph.h"
#include "metrics/edge_ratio.h"
#include "metrics/tet_deformation.h"

namespace unfold {

TetMeshFields canonical_tet_fields(const UnfoldResult& result) {
  const Eigen::MatrixX3d& P = result.tets.V;
  const Eigen::MatrixX3d& Q = result.tet_canonical;
  const EdgeGraph graph = build_edge_graph(int(P.rows()), result.tets.T);
  const TetDeformation tets = tet_deformation(P, Q, result.tets.T);
  TetMeshFields fields;
  fields.per_vertex = {{"stretch_ratio", vertex_edge_ratio(graph, P, Q)}};
  if (!std::isnan(result.metrics.E_rig))  // E_rig computed (metrics.compute)
    fields.per_vertex.insert(fields.per_vertex.begin(),
                             {"rigidity_error", result.metrics.rigidity_per_vertex});
  // The surface edges' damage on the surface vertices (the first rows), 0 inside.
  const Eigen::VectorXd& damage = result.metrics.damage.per_vertex;
  if (damage.size() > 0 && damage.size() <= P.rows()) {
    Eigen::VectorXd edge_damage = Eigen::VectorXd::Zero(P.rows());
    edge_damage.head(damage.size()) = damage;
    fields.per_vertex.push_back({"edge_damage", edge_damage});
  }
  fields.per_tet = {{"volume_ratio", tets.volume_ratio}, {"rigidity", tets.rigidity}};
  return fields;
}

TetMeshFields rest_tet_fields(const UnfoldResult& result) {
  TetMeshFields fields;
  if (result.unfolded_tet_positions.rows() > 0)
    fields.per_vertex_vectors = {{"unfolded", result.unfolded_tet_positions}};
  return fields;
}

}  // namespace unfold
