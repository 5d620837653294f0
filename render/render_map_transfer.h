// A point-to-point map drawn the way people check one: a colour on the source
// carried to the target through the map, both side by side.
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "render/image.h"

namespace unfold {

/// A smooth colour per vertex from its position: each coordinate scaled over
/// the bounding box into one RGB channel.
Eigen::MatrixX3f position_colors(const Eigen::MatrixX3d& V);

/// The target's colours through a map: each target vertex takes the mean
/// colour of the source vertices mapped to it; a vertex that none maps to takes
/// the colour of the nearest one that some vertex maps to.
/// @param source_colors one RGB row per source vertex
/// @param map one target vertex per source vertex
/// @param target_V the target's vertices
/// @throws UsageError if the sizes differ or the map names a vertex outside the target
Eigen::MatrixX3f transfer_colors(const Eigen::MatrixX3f& source_colors, const Eigen::VectorXi& map,
                                 const Eigen::MatrixX3d& target_V);

/// The source coloured by position_colors beside the target coloured through
/// the map (render_comparison: side and top views, one scale per view).
/// @param up_axis 0, 1, 2 (x, y, z) is up in both shapes
/// @throws as transfer_colors and render_comparison
Image render_map_transfer(const SurfaceMesh& source, const SurfaceMesh& target,
                          const Eigen::VectorXi& map, int up_axis);

}  // namespace unfold
