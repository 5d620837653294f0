#include "json_to_python.h"

#include <cmath>

namespace py = pybind11;

namespace unfold::python {

py::object to_python(const Json& value) {
  if (const auto* b = std::get_if<bool>(&value.value)) return py::bool_(*b);
  if (const auto* i = std::get_if<int64_t>(&value.value)) return py::int_(*i);
  // A non-finite double is null in the JSON file (JSON has no NaN): None here,
  // so that the dict holds what the file holds (e.g. a metric not computed).
  if (const auto* x = std::get_if<double>(&value.value))
    return std::isfinite(*x) ? py::object(py::float_(*x)) : py::none();
  if (const auto* s = std::get_if<std::string>(&value.value)) return py::str(*s);
  if (const auto* a = std::get_if<JsonArray>(&value.value)) {
    py::list list;
    for (const Json& item : *a) list.append(to_python(item));
    return std::move(list);
  }
  py::dict dict;
  for (const auto& [key, item] : std::get<JsonObject>(value.value))
    dict[py::str(key)] = to_python(item);
  return std::move(dict);
}

}  // namespace unfold::python
