// Finds where an input's tet mesh glues parts of the surface that touch
// (docs/method.md, contact). Where a hand rests on a thigh or legs cross, any
// tet mesh of the input's volume joins the two parts, and a canonical form
// computed on it keeps the contact. Such tets have an edge whose ends are
// near in space but far apart along the surface.
#pragma once

#include <utility>
#include <vector>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"

namespace unfold {

/// The tets that bridge a contact: those with an edge whose ends' nearest
/// surface vertices (along the tet edges; a surface vertex is its own) are
/// joined by no surface edge and are farther apart along the surface (its
/// edge graph) than both `geodesic` times the square root of the surface's
/// area and 4 times their distance in space. Across a limb the surface detour
/// is about pi/2; across a contact it is the way round through the body.
/// @param surface  the surface whose vertices are the tets' first rows
/// @param tets     its tet mesh
/// @param geodesic the reach, in units of sqrt(area) (> 0)
/// @return the indices of the bridging tets, ascending (empty: no contact)
/// @throws UsageError if the surface is not the tets' or geodesic is not positive
std::vector<int> tets_bridging_contact(const SurfaceMesh& surface, const TetMesh& tets,
                                       double geodesic);

/// Whether some tet bridges a contact (as in tets_bridging_contact): the
/// same answer as !tets_bridging_contact(...).empty(), at the cost of finding
/// one bridge instead of all (on a pose with contact most of the cost is the
/// bridges' own searches: about 1 s of david0's 1.1 s).
/// @throws UsageError as tets_bridging_contact
bool some_tet_bridges_contact(const SurfaceMesh& surface, const TetMesh& tets, double geodesic);

/// The pairs of intersecting faces that are parts of the surface passing
/// through each other: no corner of one is within `geodesic` times the square
/// root of the surface's area of a corner of the other, along the surface's
/// edge graph. Such a surface has contact before any tet mesh is made (nearby
/// faces that cross are a local defect, not contact).
/// @param surface  the surface
/// @param pairs    face pairs of triangulate_faces(surface) that intersect
///                 (intersecting_face_pairs)
/// @param geodesic the reach, in units of sqrt(area) (> 0)
/// @return how many of the pairs are far apart along the surface
/// @throws UsageError if geodesic is not positive or a face index is out of range
int count_intersections_far_along_surface(const SurfaceMesh& surface,
                                          const std::vector<std::pair<int, int>>& pairs,
                                          double geodesic);

}  // namespace unfold
