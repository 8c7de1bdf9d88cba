#pragma once
// cyclopt::SpecError (errors/spec_error.hpp) raised in Python as cyclopt.SpecError (a ValueError
// with .field, python/cyclopt/errors.py), for every module of the package.

#include <pybind11/pybind11.h>

namespace cyclopt::python {

void translate_spec_errors();

}  // namespace cyclopt::python
