#include "render/draw_2d.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace unfold {

void draw_line(double x0, double y0, double x1, double y1, Rgb color, int thickness, Image* image) {
  const double length = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
  const int steps = std::max(1, int(std::ceil(length)));
  const int lo = -(thickness - 1) / 2, hi = thickness / 2;
  for (int s = 0; s <= steps; ++s) {
    const double t = double(s) / steps;
    const int x = int(std::floor(x0 + t * (x1 - x0))), y = int(std::floor(y0 + t * (y1 - y0)));
    for (int dy = lo; dy <= hi; ++dy)
      for (int dx = lo; dx <= hi; ++dx) image->set(x + dx, y + dy, color);
  }
}

void fill_rect(int x0, int y0, int x1, int y1, Rgb color, Image* image) {
  for (int y = std::max(0, y0); y < std::min(y1, image->height); ++y)
    for (int x = std::max(0, x0); x < std::min(x1, image->width); ++x) image->set(x, y, color);
}

std::pair<int, int> text_size(const std::string& text, int scale) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  return {stb_easy_font_width(buffer.data()) * scale, stb_easy_font_height(buffer.data()) * scale};
}

void draw_text(const std::string& text, int x, int y, Rgb color, int scale, Image* image) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  // stb_easy_font emits axis-aligned quads, 4 vertices of 16 bytes each
  // (x, y, z as float, then RGBA bytes); about 270 bytes per character.
  struct Vertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  std::vector<Vertex> quads(text.size() * 80 + 64);
  stb_easy_font_spacing(0);
  const int count = stb_easy_font_print(0, 0, buffer.data(), nullptr, quads.data(),
                                        int(quads.size() * sizeof(Vertex)));
  for (int q = 0; q < count; ++q) {
    const Vertex* v = &quads[size_t(q) * 4];
    const float qx0 = std::min(v[0].x, v[2].x), qx1 = std::max(v[0].x, v[2].x);
    const float qy0 = std::min(v[0].y, v[2].y), qy1 = std::max(v[0].y, v[2].y);
    fill_rect(x + int(std::lround(qx0 * scale)), y + int(std::lround(qy0 * scale)),
              x + int(std::lround(qx1 * scale)), y + int(std::lround(qy1 * scale)), color, image);
  }
}

}  // namespace unfold
