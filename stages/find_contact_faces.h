// Stage: contact before any tet is made (tetrahedralize.shape: contact).
// Parts of the surface that pass through each other are contact, and the
// input's tets would only be checked and dropped (every such shape of
// ../shared/data also has tets bridging a contact, docs/method.md).
#pragma once

#include "mesh/surface_mesh.h"

namespace unfold {

struct ContactFaces {
  int intersecting_pairs = 0;  ///< intersecting face pairs (tetrahedralize may reuse the count)
  int contact_pairs = 0;       ///< of them, those far apart along the surface: contact
};

/// The surface's intersecting face pairs, and how many of them are parts far
/// apart along the surface (solvers/contact_bridges.h).
/// @param contact_geodesic  tetrahedralize.contact_geodesic, > 0
/// @throws UsageError if contact_geodesic is not positive
ContactFaces find_contact_faces(const SurfaceMesh& surface, double contact_geodesic);

}  // namespace unfold
