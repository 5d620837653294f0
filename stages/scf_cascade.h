// Stage: method scf, the SCF baseline (solvers/scf.h), its record in the
// shape every method's result has.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/curve_skeleton.h"
#include "mesh/edge_graph.h"
#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "solvers/cascade.h"
#include "solvers/scf.h"

namespace unfold {

struct ScfCascade {
  /// one stage: iterations = the skeleton's Guttman transforms, energy = its MDS stress
  CascadeResult cascade;
  CurveSkeleton skeleton;  ///< the input's curve skeleton
  Eigen::MatrixX3d
      skeleton_canonical;             ///< its straightened nodes (zero-mean frame, like positions)
  std::vector<std::string> warnings;  ///< the skeleton's repair left surface vertices out
};

/// Runs scf() on `tets` (the surface alone when it has no tets).
/// @param graph  the tets' edge graph (the surface's without tets)
/// @throws as scf()
ScfCascade scf_cascade(const EdgeGraph& graph, const TetMesh& tets, const SurfaceMesh& surface,
                       const ScfOptions& options);

}  // namespace unfold
