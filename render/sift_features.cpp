#include "render/sift_features.h"

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <vector>

#include "core/errors.h"

namespace unfold {

SiftDescriptors sift_descriptors(const GrayImage& image, int max_features) {
  if (image.size <= 0 || image.pixels.size() != size_t(image.size) * size_t(image.size))
    throw UsageError("SIFT: empty or malformed image");
  if (max_features < 0) throw UsageError("SIFT: max_features must be >= 0");
  // OpenCV's defaults except the descriptor type: bytes, which cache compactly.
  const cv::Ptr<cv::SIFT> sift = cv::SIFT::create(max_features, 3, 0.04, 10, 1.6, CV_8U);
  const cv::Mat pixels(image.size, image.size, CV_8UC1,
                       const_cast<std::uint8_t*>(image.pixels.data()));
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(pixels, cv::noArray(), keypoints, descriptors);
  SiftDescriptors result(descriptors.rows, 128);
  for (int i = 0; i < descriptors.rows; ++i)
    for (int k = 0; k < 128; ++k) result(i, k) = descriptors.at<std::uint8_t>(i, k);
  return result;
}

}  // namespace unfold
