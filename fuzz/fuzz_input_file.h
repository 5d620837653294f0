// Shared by the libFuzzer targets: the readers take a path, so each input is
// written to a file of this process first.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>

namespace unfold::fuzz {

/// Writes bytes to a per-process scratch file with the given extension
/// (e.g. ".off") and returns its path; the file is reused across inputs.
inline std::string write_input_file(const uint8_t* data, size_t size, const std::string& ext) {
  const std::string path = "/tmp/unfold_fuzz_" + std::to_string(getpid()) + ext;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace unfold::fuzz
