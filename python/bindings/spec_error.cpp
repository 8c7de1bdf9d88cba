#include "spec_error.hpp"

#include "cyclopt/errors/spec_error.hpp"

#include <algorithm>

namespace cyclopt::python {

void translate_spec_errors() {
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SpecError& e) {
      namespace py = pybind11;
      const std::string what = e.what();
      const std::string message = what.substr(std::min(what.size(), e.field().size() + 2));
      py::object error = py::module_::import("cyclopt.errors").attr("SpecError")(e.field(), message);
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    }
  });
}

}  // namespace cyclopt::python
