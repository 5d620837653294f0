#include "render/image.h"

#include <algorithm>

namespace unfold {

Image::Image(int w, int h, Rgb background) : width(std::max(w, 0)), height(std::max(h, 0)) {
  pixels.resize(size_t(width) * size_t(height) * 3);
  for (size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = background.r;
    pixels[i + 1] = background.g;
    pixels[i + 2] = background.b;
  }
}

Rgb Image::at(int x, int y) const {
  const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void Image::set(int x, int y, Rgb color) {
  if (!contains(x, y)) return;
  const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
  pixels[i] = color.r;
  pixels[i + 1] = color.g;
  pixels[i + 2] = color.b;
}

void paste(const Image& src, int x, int y, Image* dst) {
  for (int sy = 0; sy < src.height; ++sy)
    for (int sx = 0; sx < src.width; ++sx) dst->set(x + sx, y + sy, src.at(sx, sy));
}

Image downsample(const Image& image, int factor) {
  Image out(image.width / factor, image.height / factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const Rgb c = image.at(x * factor + dx, y * factor + dy);
          sum[0] += c.r;
          sum[1] += c.g;
          sum[2] += c.b;
        }
      const int n = factor * factor;
      out.set(x, y,
              {std::uint8_t((sum[0] + n / 2) / n), std::uint8_t((sum[1] + n / 2) / n),
               std::uint8_t((sum[2] + n / 2) / n)});
    }
  return out;
}

}  // namespace unfold
