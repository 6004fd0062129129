#pragma once
// The parts of the coolinggen extension module (module.cpp calls them in order).
#include <pybind11/pybind11.h>

namespace cg::python {

void bind_build(pybind11::module_& m);   // build, validate, example, Result, __version__
void bind_kernel(pybind11::module_& m);  // BSplineCurve, BSplineSurface (NumPy arrays)

}  // namespace cg::python
