// The extension module coolinggen._coolinggen; python/coolinggen/__init__.py re-exports it.
#include "python/src/bind.hpp"
#include "python/src/errors.hpp"

PYBIND11_MODULE(_coolinggen, m) {
  m.doc() = "CoolingGen: verified CAD models of cooled turbine blades (units mm, degrees)";
  cg::python::bind_errors(m);
  cg::python::bind_build(m);
  cg::python::bind_kernel(m);
}
