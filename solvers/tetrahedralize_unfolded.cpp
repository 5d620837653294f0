#include "solvers/tetrahedralize_unfolded.h"

#include <cmath>
#include <utility>

#include "core/errors.h"
#include "mesh/drop_inverted_tets.h"
#include "mesh/edge_graph.h"
#include "mesh/sort_interior_vertices.h"
#include "metrics/pose_invariance.h"
#include "solvers/arap_solve.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {
namespace {

// The interior rows of X (rows num_fixed and up) as the uniform-weight
// harmonic extension of the held rows: ARAP's start, inside the input surface
// wherever the surface is not too far from convex.
void harmonic_fill(const EdgeGraph& graph, int num_fixed, Eigen::MatrixX3d* X) {
  const int m = graph.num_vertices - num_fixed;
  if (m == 0) return;
  const Eigen::SparseMatrix<double> L = graph_laplacian(graph);
  const Eigen::SparseMatrix<double> L_ii = L.bottomRightCorner(m, m);
  const Eigen::SparseMatrix<double> L_ib = L.bottomLeftCorner(m, num_fixed);
  SparseLdlt ldlt;
  ldlt.analyze(L_ii);
  try {
    ldlt.factorize(L_ii);
  } catch (const NumericalError&) {
    throw NumericalError(
        "the unfolded shape's tet mesh has interior vertices joined to no "
        "surface vertex");
  }
  Eigen::MatrixX3d interior;
  ldlt.solve(-(L_ib * X->topRows(num_fixed)), &interior);
  X->bottomRows(m) = interior;
}

}  // namespace

double input_interior_spacing(const SurfaceMesh& input, const Eigen::MatrixX3d& S) {
  const Eigen::MatrixX3i F = triangulate_faces(input);
  return kInteriorSpacingEdges * mean_edge_length(input.V, F) *
         std::sqrt(surface_area(S, F) / surface_area(input.V, F));
}

UnfoldedTetMesh tetrahedralize_unfolded(const SurfaceMesh& input, const Eigen::MatrixX3d& S,
                                        const TetOptions& options, bool surface_edges_join,
                                        int placement_iterations) {
  const int ns = int(input.V.rows());
  if (S.rows() != ns)
    throw UsageError("tetrahedralize_unfolded: the unfolded surface has " +
                     std::to_string(S.rows()) + " vertices, the input " + std::to_string(ns));
  UnfoldedTetMesh out;
  const SurfaceMesh unfolded{S, input.faces};
  TetMesh tets = tetrahedralize(unfolded, options, &out.report);
  sort_interior_vertices(&tets);
  const int n = int(tets.V.rows());

  // S is inflated (its edges about 2-3 times the input's): its tets, scaled to
  // the input's area, are the shapes the interior keeps while it is put into
  // the input (ARAP ignores rotation, not scale).
  const Eigen::MatrixX3i F = triangulate_faces(input);
  const double scale = std::sqrt(surface_area(input.V, F) / surface_area(S, F));
  const Eigen::MatrixX3d reference = tets.V * scale;
  const EdgeGraph graph = build_edge_graph(n, Eigen::MatrixXi(tets.T));
  Eigen::MatrixX3d X(n, 3);
  X.topRows(ns) = input.V;
  harmonic_fill(graph, ns, &X);
  if (n > ns) {
    ArapSolveOptions place;
    place.num_fixed = ns;
    place.max_iterations = placement_iterations;
    X = arap_solve(graph, reference, std::move(X), place);
  }
  out.report.shape = "unfolded";
  // Flat tets across the surface that turn inside out in the input (19 % of
  // david0's): without them E_rig of cat is 0.68 -> 0.49 and its pose ratio
  // 0.29 -> 0.22 (docs/method.md, contact).
  // When the solve joins the surface's edges, no inverted tet is kept only to
  // join surface vertices: what it would hold them by has no rest shape.
  // Slivers of the robust route's Delaunay, and tets flattened when put back,
  // have no rest shape either: a small turn of a corner flips them
  // (options.unfolded_min_quality; docs/method.md, detail).
  const Eigen::MatrixXi surface_edges = Eigen::MatrixXi(F);
  const DroppedTets dropped =
      drop_inverted_tets(tets.V, X, &tets.T, surface_edges_join ? &surface_edges : nullptr,
                         options.unfolded_min_quality);
  out.report.inverted_rest_tets = dropped.kept_inverted;
  out.report.dropped_inverted_tets = dropped.inverted;
  out.report.dropped_flat_tets = dropped.flat;
  out.report.num_tets = int(tets.T.rows());
  out.unfolded = std::move(tets.V);
  out.rest = std::move(tets);
  out.rest.V = std::move(X);
  return out;
}

}  // namespace unfold
