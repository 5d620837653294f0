// Memory order of a tet mesh's interior vertices. TetGen numbers its Steiner
// points in insertion order, scattered over the volume, so every sweep over the
// mesh (sparse products, AMG cycles, Dijkstra, the local step) keeps missing
// the cache. Sorting them along a space-filling curve puts spatial neighbours
// next to each other in memory (docs/history/performance.md: 1.3-1.6x on those sweeps).
#pragma once

#include "mesh/tet_mesh.h"

namespace unfold {

/// Renumbers the interior vertices (rows num_surface_vertices and up) in
/// Morton (Z-curve) order of their positions, ties by old index; the surface
/// vertices keep their rows. T is renumbered to match: the same mesh.
void sort_interior_vertices(TetMesh* tets);

}  // namespace unfold
