// Inverted tets mended by moving their corners a little. A deformation solved
// edge by edge (ARAP on one-ring cells) does not see a tet's orientation: a
// tet nearly flat at rest (a sliver of four surface vertices, or one made on the
// unfolded shape and flattened when put back into the input) turns inside out
// at the cost of a small fraction of an edge, and many do (docs/method.md,
// detail). Pushing each back out is a projection onto its volume constraint,
// one tet at a time (Gauss-Seidel), its corners weighted by how finely the
// mesh is made there so that a densely meshed face moves less than the body.
#pragma once

#include <Eigen/Core>

namespace unfold {

struct UntangleOptions {
  int sweeps = 0;  ///< passes over the tets below their target volume at most; 0: off
  /// how far a vertex may move in all, times h (its shortest rest edge, below):
  /// a tet that cannot be mended within it is left inverted
  double max_move = 0.2;
};

/// What untangle_tets did.
struct UntangleReport {
  int inverted_before = 0;  ///< tets inverted in the positions given
  int inverted_after = 0;   ///< and in the positions returned
  int moved_vertices = 0;
  double largest_move = 0;  ///< the largest move of a vertex, relative to its h
  int sweeps = 0;           ///< passes made
};

/// Pushes the tets inverted in Q (their signed volume has lost the sign it has
/// at `made`: count_inverted_tets' test) back out. Each pass visits, in row
/// order, the tets whose volume with that sign is below a tenth of their rest
/// volume and moves corner k by lambda h_k^2 grad_k V, h_k the shortest rest
/// edge at the corner (of a tet or of a face): the least move, in units of h,
/// that gives the tet that volume to first order. No vertex moves more than
/// max_move h in all; the passes stop once no tet is inverted.
/// @param made  positions T was made at (their volumes' signs are the orientation)
/// @param rest  rest positions (the target volumes, h)
/// @param T     tets, rows of corner indices
/// @param Q     positions to mend, changed in place
/// @param faces optional rows of vertices joined otherwise (the surface's
///        triangles): their edges count toward h too, so that a surface edge no
///        tet has (shorter than the tets' at its ends) is not stretched
/// @throws UsageError if the positions' sizes differ, a corner or a face's
///         vertex is out of range, sweeps < 0 or max_move is not finite and >= 0
UntangleReport untangle_tets(const Eigen::MatrixX3d& made, const Eigen::MatrixX3d& rest,
                             const Eigen::MatrixX4i& T, const UntangleOptions& options,
                             Eigen::MatrixX3d* Q, const Eigen::MatrixXi* faces = nullptr);

}  // namespace unfold
