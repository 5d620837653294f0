// Depth-buffer views of a shape (CM-BOF's views, Lian et al. 2013): the shape
// seen orthographically along a direction, each pixel's grey level the
// nearness of the surface there, background black.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace unfold {

/// An 8-bit grey image, row-major, top row first.
struct GrayImage {
  int size = 0;                      ///< width = height
  std::vector<std::uint8_t> pixels;  ///< size * size
};

/// The depth image of (V, F) seen from `direction` (towards the origin): the
/// square [-1, 1]^2 of the view plane fills the image, the pixel's grey level
/// is 255 (1 - d / 2) for the nearest surface point at distance d from the
/// plane one unit in front of the origin, 0 where no surface is. The screen's
/// axes are fixed by the direction alone (its up is the world axis least
/// parallel to it, made orthogonal).
/// @pre V inside the unit ball (a normalised shape), direction of unit length
/// @throws UsageError for size < 8
GrayImage depth_image(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                      const Eigen::Vector3d& direction, int size);

}  // namespace unfold
