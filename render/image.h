// An 8-bit RGB raster image, the common currency of the renderer and the plots.
#pragma once

#include <cstdint>
#include <vector>

namespace unfold {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
  bool operator!=(const Rgb& o) const { return !(*this == o); }
};

/// Row-major RGB pixels, top row first (PNG order).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< 3 bytes per pixel

  Image() = default;
  /// A width x height image filled with `background`. Negative sizes count as 0.
  Image(int width, int height, Rgb background = {255, 255, 255});

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  /// The pixel at (x, y); precondition: contains(x, y).
  Rgb at(int x, int y) const;
  /// Sets (x, y); pixels outside the image are ignored (drawing clips).
  void set(int x, int y, Rgb color);
};

/// Copies `src` into `dst` with its top-left corner at (x, y), clipped to `dst`.
void paste(const Image& src, int x, int y, Image* dst);

/// Averages factor x factor blocks (anti-aliasing after supersampled drawing).
/// Precondition: factor >= 1; trailing rows/columns that do not fill a block are dropped.
Image downsample(const Image& image, int factor);

}  // namespace unfold
