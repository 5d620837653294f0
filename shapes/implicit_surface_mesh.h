// Meshes the zero level set of a smooth implicit function into a closed,
// 2-manifold, outward-oriented triangle mesh of roughly uniform edge length.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Signed field: negative inside the solid, positive outside.
using ImplicitFunction = std::function<double(const Eigen::Vector3d&)>;

/// Meshes {x : f(x) = 0}: marching tetrahedra on a fine grid (watertight and
/// manifold by construction), quadric edge-collapse decimation to the vertex
/// count an equilateral mesh with edges of `edge_length` would have, then
/// isotropic remeshing (split, collapse, flip, tangential smoothing) with
/// projection back onto the level set.
/// Deterministic. Normals point towards f > 0.
/// @param f            field; thread-safe (it is evaluated in parallel)
/// @param box          region to sample; f must be > 0 on its boundary
/// @param edge_length  target edge length, > 0
/// @param grid_spacing marching grid step, in (0, edge_length]; should be below
///                     a third of the thinnest feature's radius or the feature
///                     may break up; at most 1e8 grid points
/// @throws UsageError on bad lengths or an empty level set
SurfaceMesh mesh_implicit_surface(const ImplicitFunction& f, const Eigen::AlignedBox3d& box,
                                  double edge_length, double grid_spacing);

}  // namespace unfold
