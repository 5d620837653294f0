// libFuzzer target for the config reader: arbitrary bytes as a YAML config.
// Only UsageError may come out, and a configuration that loads must survive
// a round trip through options_to_yaml unchanged.
#include <cstdint>
#include <string>

#include "config/options.h"
#include "core/errors.h"
#include "fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string yaml;
  try {
    yaml = unfold::options_to_yaml(
        unfold::load_options(unfold::fuzz::write_input_file(data, size, ".yaml")));
  } catch (const unfold::UsageError&) {
    return 0;
  }
  const uint8_t* text = reinterpret_cast<const uint8_t*>(yaml.data());
  const std::string again = unfold::options_to_yaml(
      unfold::load_options(unfold::fuzz::write_input_file(text, yaml.size(), ".yaml")));
  if (again != yaml) __builtin_trap();
  return 0;
}
