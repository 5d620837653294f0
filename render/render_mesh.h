// A shaded triangle mesh drawn into a canvas through an orthographic view.
#pragma once

#include <Eigen/Core>

#include "render/camera.h"
#include "render/rasterize.h"

namespace unfold {

enum class Shading { kFlat, kGouraud };

/// Draws the triangles F of V, lit by a headlight (two-sided Lambert plus
/// ambient, so inconsistently oriented faces still read), centred in the canvas.
/// @param colors per-vertex base colours (V.rows() x 3, RGB in [0, 1]) or empty for one
///               neutral colour; with kFlat each face takes its corners' mean colour
/// @param scale  pixels per unit (common_scale, so shapes in one view compare)
/// @throws UsageError if colors is non-empty and has the wrong size, or F indexes outside V
void render_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                 const Eigen::MatrixX3f& colors, const View& view, double scale, Shading shading,
                 Canvas* canvas);

/// render_mesh() with the point `centre` at the canvas centre instead of V's
/// bounding box's centre: a close-up, the triangles reaching outside the
/// canvas clipped by the rasteriser.
void render_mesh_about(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                       const Eigen::MatrixX3f& colors, const View& view,
                       const Eigen::Vector3d& centre, double scale, Shading shading,
                       Canvas* canvas);

}  // namespace unfold
