// The silhouette of a shape seen along a coordinate axis, counted in pixels:
// ORT's choice between the PCA and the rectilinearity orientation
// (metrics/ort_dissimilarity.h) keeps the one whose three axis views cover
// fewer pixels, as the public reimplementation of CM-BOF does (Pickup,
// github.com/davidpickup/view-based-3d-shape-retrieval, which counts the
// object pixels of three 256 x 256 orthographic depth images). Occupancy needs
// neither depth nor colour, and the metrics layer may not use render/'s
// rasterizer, so this covers pixels by the same rule on a grid of its own.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// The number of pixels of a resolution x resolution grid over the square
/// [-1, 1]^2 whose centres lie inside (or on an edge of) the projection of a
/// triangle of (V, F) along coordinate axis `axis`; the grid's coordinates are
/// the two other axes in increasing order. What falls outside the square is
/// not counted; a triangle seen edge-on covers nothing.
/// @throws UsageError for an axis outside 0..2 or resolution < 1
long silhouette_pixels(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int axis,
                       int resolution);

}  // namespace unfold
