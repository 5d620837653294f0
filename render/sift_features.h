// SIFT descriptors (Lowe 2004) of a grey image, the local features of CM-BOF's
// depth views. The one file of the library that uses OpenCV (cv::SIFT of
// libopencv-features2d), so that its headers stay out of the others.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "render/depth_image.h"

namespace unfold {

/// One SIFT descriptor per row: 128 bytes (OpenCV's 8-bit descriptors).
using SiftDescriptors = Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 128, Eigen::RowMajor>;

/// The descriptors of the keypoints OpenCV's SIFT detects in `image` with its
/// default parameters (3 layers per octave, contrast threshold 0.04, edge
/// threshold 10, sigma 1.6), at most `max_features` of the strongest (0: all),
/// in OpenCV's order. Deterministic for a given image.
/// @throws UsageError for an empty image or max_features < 0
SiftDescriptors sift_descriptors(const GrayImage& image, int max_features);

}  // namespace unfold
