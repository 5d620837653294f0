// A library Json document as Python objects: dict (in the document's key
// order), list, bool, int, float (non-finite numbers stay float: nan, inf), str.
#pragma once

#include <pybind11/pybind11.h>

#include "core/json.h"

namespace unfold::python {

pybind11::object to_python(const Json& value);

}  // namespace unfold::python
