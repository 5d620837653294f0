#include "stages/anchor_lambda2.h"

#include "mesh/edge_graph.h"
#include "solvers/fiedler_value.h"

namespace unfold {

double anchor_lambda2(const SurfaceMesh& surface) {
  return fiedler_value(graph_laplacian(
      build_edge_graph(int(surface.V.rows()), Eigen::MatrixXi(triangulate_faces(surface)))));
}

}  // namespace unfold
