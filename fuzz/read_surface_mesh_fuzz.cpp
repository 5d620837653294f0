// libFuzzer target for the surface mesh readers (every format) and the mesh
// checks. The first byte picks the extension, the rest is the file. Any
// exception other than unfold::Error, and any sanitizer report, is a bug.
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "fuzz/fuzz_input_file.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/read_surface_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string path =
      unfold::fuzz::write_input_file(data + 1, size - 1, kExtensions[data[0] % 4]);
  try {
    const unfold::SurfaceMesh mesh = unfold::read_surface_mesh(path);
    unfold::check_surface_mesh(mesh, false);
  } catch (const unfold::Error&) {
  }
  return 0;
}
