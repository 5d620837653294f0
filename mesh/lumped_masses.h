// Lumped vertex masses: each vertex's share of the volume (tet mesh) or of the
// area (triangle mesh), the diagonal of the lumped mass matrix. They make a
// per-vertex sum an integral over the shape, independent of how it is meshed.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// m_i = sum over the tets at vertex i of |volume| / 4.
/// @throws InputError if some vertex gets no volume (in no tet, or only in flat ones)
Eigen::VectorXd lumped_masses(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T);

/// m_i = sum over the triangles at vertex i of area / 3.
/// @throws InputError if some vertex gets no area (in no triangle, or only in flat ones)
Eigen::VectorXd lumped_masses(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

}  // namespace unfold
