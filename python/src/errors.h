// The library's typed exceptions as Python exceptions under one unfold.Error.
#pragma once

#include <pybind11/pybind11.h>

namespace unfold::python {

/// Defines Error, ConfigError, InputError, NumericalError and OutputError in
/// module m and translates the C++ classes (UsageError -> ConfigError) into
/// them, message unchanged: the CLI's one-line message without "unfold: error: ".
void register_errors(pybind11::module_& m);

}  // namespace unfold::python
