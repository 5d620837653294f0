// Memory order of a tet mesh's interior vertices. TetGen numbers its Steiner
// points in insertion order, scattered over the volume, so every sweep over the
// mesh (sparse products, AMG cycles, Dijkstra, the local step) keeps missing
// the cache. Sorting them along a space-filling curve puts spatial neighbours
// next to each other in memory (docs/history/performance.md: 1.3-1.6x on those sweeps).
#pragma once

#include "mesh/tet_mesh.h"

namespace unfold {

/// Renumbers the interior vertices (rows num_surface_vertices and up) in
/// Morton (Z-curve) order of their positions (locality_order), ties by old index; the surface
/// vertices keep their rows. T is renumbered to match: the same mesh.
/// @param made optional other positions of the same vertices (where the tets
///        were made, e.g. the unfolded shape's): the order is theirs, and their
///        rows are renumbered too, so that a mesh sorted by them keeps its order
/// @throws UsageError if made's row count differs from the mesh's
void sort_interior_vertices(TetMesh* tets, Eigen::MatrixX3d* made = nullptr);

}  // namespace unfold
