// Stage: the edges every stage after the tets are made solves and measures on.
#pragma once

#include <string>
#include <vector>

#include "mesh/edge_graph.h"
#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"

namespace unfold {

struct SolveEdges {
  EdgeGraph graph;
  /// surface_weight > 0: the integration's weight factor of each edge of graph
  /// (surface_weight on the surface's edges that no tet has, else 1); else empty
  std::vector<double> integrate_factors;
  std::vector<std::string> warnings;  ///< tet edges left out (coinciding ends)
};

/// The tets' edges (the triangles' without tets), joined with the surface's
/// when `surface_weight` > 0 (integrate.surface_edges,
/// mesh/tet_and_surface_edge_graph.h). The metrics measure on the same edges:
/// the paper's tets (TetGen's, conforming) have every surface edge too.
/// @throws NumericalError when the graph is not connected or an edge has zero
///         length (the solver divides by rest lengths)
SolveEdges solve_edge_graph(const TetMesh& tets, const SurfaceMesh& surface, double surface_weight);

}  // namespace unfold
