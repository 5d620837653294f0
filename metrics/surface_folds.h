// Folds of a canonical form: how much sharper the surface bends at each edge
// than the input did there. A face crumpled with its edge lengths kept (an
// isometric fold) passes the edge-ratio damage measure (metrics/surface_damage.h);
// the sharpened dihedral angle sees it (issue 44). A crease of the input that
// opens (a bent joint straightened: its inner skin fold goes flat) is what
// unfolding should do, and is no fold.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// An edge is folded when its bend sharpens by more than this many degrees (a
/// right angle: the surface there turned over against its neighbour); the
/// per-vertex values and the percentiles are in degrees.
constexpr double kFoldedDegrees = 90;
/// The same bound in radians, the unit surface_folds() takes.
constexpr double kFoldedDihedralChange = kFoldedDegrees * 3.14159265358979323846 / 180;

/// The fold measure of one triangle surface in two positions (see surface_folds()).
struct SurfaceFolds {
  int edges = 0;                    ///< edges with exactly two non-degenerate triangles in both
  int folded_edges = 0;             ///< measured edges whose change (sharpening) exceeds the bound
  double folded_edges_percent = 0;  ///< 100 * folded_edges / edges, in [0, 100]
  /// the 99.9th percentile of the change, nearest rank, in degrees
  double dihedral_change_p999 = 0;
  double dihedral_change_max = 0;  ///< the largest change, in degrees
  /// per vertex: the largest change of its measured edges, in degrees (0: none)
  Eigen::VectorXd per_vertex;
};

/// The sharpening of the bend at each interior edge: for the edge (a, b) between
/// triangles with normals n1 and n2, the signed dihedral angle theta =
/// atan2((n1 x n2) . e, n1 . n2) (0: flat), e the unit edge direction; the
/// change is max(0, |theta_out| - |theta_in|), in [0, 180) degrees: a smooth
/// part turned over counts, an input crease opening or turning the other way
/// does not. Invariant to rigid motions and scaling of either position, and to
/// edge lengths: a surface bent without stretching shows here.
/// Edges with one triangle (a border) or more than two, and triangles of zero
/// area in either position, are left out. Deterministic, O(F log F).
/// @param V_in  rest positions (n x 3)
/// @param V_out deformed positions (n x 3), the same rows
/// @param F     triangles (rows of vertex indices into both)
/// @param bound an edge is folded when its change exceeds this, radians in (0, pi)
/// @throws UsageError if V_in and V_out differ in rows, bound is not in (0, pi),
///         or a triangle's index is outside [0, n)
SurfaceFolds surface_folds(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                           const Eigen::MatrixX3i& F, double bound = kFoldedDihedralChange);

}  // namespace unfold
