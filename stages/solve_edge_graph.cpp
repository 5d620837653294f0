#include "stages/solve_edge_graph.h"

#include <glog/logging.h>

#include "core/errors.h"
#include "mesh/tet_and_surface_edge_graph.h"

namespace unfold {
namespace {

EdgeGraph graph_of(const TetMesh& tets, const SurfaceMesh& surface, double surface_weight,
                   SolveEdges* out) {
  if (tets.T.rows() == 0)
    return build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(triangulate_faces(surface)));
  if (!(surface_weight > 0)) return build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(tets.T));
  int zero_length = 0;
  std::vector<char> surface_only;
  EdgeGraph graph = tet_and_surface_edge_graph(tets.V, tets.T, triangulate_faces(surface),
                                               &surface_only, &zero_length);
  if (zero_length > 0) {
    out->warnings.push_back(std::to_string(zero_length) +
                            " tet edges join vertices that coincide in the input and share no "
                            "triangle (a contact): left out of the solve");
    LOG(WARNING) << out->warnings.back();
  }
  out->integrate_factors.resize(surface_only.size());
  for (size_t e = 0; e < surface_only.size(); ++e)
    out->integrate_factors[e] = surface_only[e] ? surface_weight : 1.0;
  return graph;
}

}  // namespace

SolveEdges solve_edge_graph(const TetMesh& tets, const SurfaceMesh& surface,
                            double surface_weight) {
  SolveEdges out;
  out.graph = graph_of(tets, surface, surface_weight, &out);
  const EdgeGraph& graph = out.graph;
  const int components = connected_components(graph);
  if (components != 1)
    throw NumericalError("the tet mesh's edge graph has " + std::to_string(components) +
                         " connected components; unfolding needs one");
  for (int e = 0; e < graph.num_edges(); ++e)
    if ((tets.V.row(graph.edges(e, 0)) - tets.V.row(graph.edges(e, 1))).norm() == 0)
      throw NumericalError("tet mesh edge " + std::to_string(graph.edges(e, 0)) + "-" +
                           std::to_string(graph.edges(e, 1)) + " has zero length");
  return out;
}

}  // namespace unfold
