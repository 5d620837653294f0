// PNG output through stb_image_write (Debian's libstb-dev).
#pragma once

#include <string>

#include "render/image.h"

namespace unfold {

/// Throws OutputError unless path is empty or ends in .png (checked before long work).
void check_png_format(const std::string& path);

/// Writes `image` as an 8-bit RGB PNG, atomically.
/// @throws OutputError for a non-.png path, an empty image or a failed write (no partial file)
void write_png(const std::string& path, const Image& image);

}  // namespace unfold
