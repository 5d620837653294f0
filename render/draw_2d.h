// 2D drawing on an image: lines, rectangles and text (stb_easy_font's tiny
// built-in segment font, scaled by whole pixels), for plots and captions.
#pragma once

#include <string>
#include <utility>

#include "render/image.h"

namespace unfold {

/// A line from (x0, y0) to (x1, y1) in pixels, `thickness` pixels wide (square pen).
/// Parts outside the image are clipped.
void draw_line(double x0, double y0, double x1, double y1, Rgb color, int thickness, Image* image);

/// Fills the pixels x in [x0, x1), y in [y0, y1), clipped.
void fill_rect(int x0, int y0, int x1, int y1, Rgb color, Image* image);

/// Text size in pixels at `scale` (pixels per font unit, >= 1): {width, height}.
std::pair<int, int> text_size(const std::string& text, int scale);

/// Draws ASCII text with its top-left corner at (x, y); '\n' starts a new line.
void draw_text(const std::string& text, int x, int y, Rgb color, int scale, Image* image);

}  // namespace unfold
