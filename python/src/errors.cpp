#include "errors.h"

#include <new>

#include "core/errors.h"

namespace py = pybind11;

namespace unfold::python {

void register_errors(py::module_& m) {
  // Also built-in exception classes, so code that catches ValueError or
  // OSError around any library call keeps working.
  static py::exception<Error> base(m, "Error");
  const auto subclass = [&](const char* name, PyObject* builtin) {
    return py::exception<void>(m, name, py::make_tuple(base, py::handle(builtin)));
  };
  static py::exception<void> config = subclass("ConfigError", PyExc_ValueError);
  static py::exception<void> input = subclass("InputError", PyExc_ValueError);
  static py::exception<void> numerical = subclass("NumericalError", PyExc_RuntimeError);
  static py::exception<void> output = subclass("OutputError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UsageError& e) {
      config(e.what());
    } catch (const InputError& e) {
      input(e.what());
    } catch (const NumericalError& e) {
      numerical(e.what());
    } catch (const OutputError& e) {
      output(e.what());
    } catch (const Error& e) {
      base(e.what());
    }
  });
}

}  // namespace unfold::python
