#include "render/write_png.h"

#include <stb/stb_image_write.h>

#include <ostream>

#include "core/atomic_file.h"
#include "core/errors.h"

namespace unfold {
namespace {

void write_to_stream(void* context, void* data, int size) {
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

}  // namespace

void check_png_format(const std::string& path) {
  const std::string suffix = ".png";
  if (!path.empty() && (path.size() < suffix.size() ||
                        path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0))
    throw OutputError("unsupported image format '" + path + "' (use .png)");
}

void write_png(const std::string& path, const Image& image) {
  check_png_format(path);
  if (image.width <= 0 || image.height <= 0)
    throw OutputError("cannot write an empty image to '" + path + "'");
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        if (!stbi_write_png_to_func(write_to_stream, &out, image.width, image.height, 3,
                                    image.pixels.data(), image.width * 3))
          throw OutputError("PNG encoding failed for '" + path + "'");
      },
      true);
}

}  // namespace unfold
