#include "pipeline/prepare_mesh_from_tets.h"

#include <glog/logging.h>

#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/sort_interior_vertices.h"
#include "mesh/tet_mesh_boundary.h"

namespace unfold {

PreparedMesh prepare_mesh_from_tets(const SurfaceMesh& surface, const Eigen::MatrixX3d& V,
                                    const Eigen::MatrixX4i& T, const Options& options,
                                    const Eigen::MatrixX3d& unfolded) {
  validate_options(options);
  if (unfolded.size() > 0 && unfolded.rows() != V.rows())
    throw UsageError("prepare_mesh_from_tets: " + std::to_string(unfolded.rows()) +
                     " unfolded positions for " + std::to_string(V.rows()) + " tet vertices");
  if (options.target_vertices > 0)
    throw UsageError(
        "simplify.target_vertices does not apply to a given tet mesh (it is used as "
        "it is); leave it 0");
  if (options.tet_shape == "unfolded")
    throw UsageError(
        "tetrahedralize.shape: unfolded makes a tet mesh of the surface solve's shape instead of "
        "the given one; leave it auto or input");
  PreparedMesh prepared;
  prepared.warnings = check_surface_mesh(surface, true).warnings;
  for (const auto& w : prepared.warnings) LOG(WARNING) << w;
  std::string mismatch;
  const Eigen::VectorXi surface_row = match_tet_mesh_boundary(surface, V, T, &mismatch);
  if (!mismatch.empty()) {
    // A carved tet mesh (the robust route's, the default's --rest_tet_output)
    // holds the surface's vertices without its every triangle on its boundary.
    prepared.warnings.push_back("the tet mesh's boundary is not exactly the surface: " + mismatch);
    LOG(WARNING) << prepared.warnings.back();
  }

  // New row of each old one: the surface's first, the others after them in order.
  const int n = int(V.rows()), ns = int(surface.V.rows());
  std::vector<int> new_row(size_t(n), -1);
  for (int i = 0; i < ns; ++i) new_row[size_t(surface_row[i])] = i;
  std::vector<bool> used(size_t(n), false);
  for (Eigen::Index k = 0; k < T.size(); ++k) used[size_t(T.data()[k])] = true;
  int next = ns;
  // A surface vertex may be in no tet (the default's rest tets leave some
  // to the surface's edges); a vertex off the surface has nothing else.
  for (int v = 0; v < n; ++v) {
    if (new_row[size_t(v)] >= 0) continue;
    if (!used[size_t(v)])
      throw InputError("tet mesh vertex " + std::to_string(v) +
                       " is in no tetrahedron and not on the surface");
    new_row[size_t(v)] = next++;
  }
  TetMesh& tets = prepared.tets;
  tets.V.resize(n, 3);
  for (int v = 0; v < n; ++v) tets.V.row(new_row[size_t(v)]) = V.row(v);
  tets.T = T.unaryExpr([&new_row](int v) { return new_row[size_t(v)]; });
  tets.num_surface_vertices = ns;
  if (unfolded.size() > 0) {
    // In the order of where they were made: the order the run that wrote them had.
    Eigen::MatrixX3d& made = prepared.unfolded_tet_positions;
    made.resize(n, 3);
    for (int v = 0; v < n; ++v) made.row(new_row[size_t(v)]) = unfolded.row(v);
    sort_interior_vertices(&tets, &made);
  } else {
    sort_interior_vertices(&tets);
  }
  prepared.surface = surface;
  prepared.tet_report.route = "given";
  prepared.tet_report.num_tets = int(T.rows());
  prepared.tet_report.num_interior_points = n - ns;
  LOG(INFO) << "given tet mesh: " << n << " vertices (" << ns << " on the surface), " << T.rows()
            << " tets";
  return prepared;
}

}  // namespace unfold
