#include "stages/find_contact_faces.h"

#include <glog/logging.h>

#include "solvers/contact_bridges.h"
#include "tetra/intersecting_faces.h"

namespace unfold {

ContactFaces find_contact_faces(const SurfaceMesh& surface, double contact_geodesic) {
  const auto pairs = intersecting_face_pairs(surface.V, triangulate_faces(surface));
  ContactFaces out;
  out.intersecting_pairs = int(pairs.size());
  out.contact_pairs = count_intersections_far_along_surface(surface, pairs, contact_geodesic);
  if (out.contact_pairs > 0)
    LOG(INFO) << out.contact_pairs << " of the surface's " << out.intersecting_pairs
              << " intersecting face pairs are parts passing through each other: "
                 "tetrahedralizing the unfolded shape";
  return out;
}

}  // namespace unfold
