// The edges a solve on a tet mesh uses when the tets need not carry the
// surface: the robust route tetrahedralizes an unfolded shape by an
// unconstrained Delaunay, which leaves some of the surface's own edges out,
// and put back into the input the tets around a closed mouth or pressed
// fingers invert and are dropped. The surface's edges are then the only rest
// geometry left there; without them a surface vertex hangs on chords through
// the volume, and the integration pulls it out as a needle (docs/method.md,
// the default stage by stage).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

/// The edge graph of the tets T joined with the edges of the triangles F,
/// less the tet edges of zero length at P: two distinct vertices that coincide
/// at rest and are joined by no triangle (a contact of the input, such as two
/// lips meshed onto one point) have no rest vector to keep, and inverse-length
/// weights cannot weigh them.
/// @param P positions at rest (rows: vertices); T's and F's corners index them
/// @param T tets (may be empty)
/// @param F triangles of the surface (rows of 3 vertex indices)
/// @param surface_only optional: per edge of the result (its order), 1 where the
///        edge is a triangle's and no tet's, else 0
/// @param zero_length_dropped optional: how many tet edges of zero length were left out
/// @throws UsageError if a corner of T or F is not a row of P
EdgeGraph tet_and_surface_edge_graph(const Eigen::MatrixX3d& P, const Eigen::MatrixX4i& T,
                                     const Eigen::MatrixX3i& F,
                                     std::vector<char>* surface_only = nullptr,
                                     int* zero_length_dropped = nullptr);

}  // namespace unfold
