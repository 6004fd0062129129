#include "python/src/errors.hpp"

#include <Standard_Failure.hxx>

#include <cctype>

#include "export/atomic_file.hpp"
#include "src/config/config_error.hpp"
#include "src/core/progress.hpp"

namespace py = pybind11;

namespace cg::python {
namespace {

// The classes live as long as the module (which holds a reference to each).
PyObject* g_error = nullptr;
PyObject* g_config_error = nullptr;
PyObject* g_feature_failure = nullptr;
PyObject* g_cancelled = nullptr;
PyObject* g_output_error = nullptr;
PyObject* g_geometry_error = nullptr;

PyObject* new_class(py::module_& m, const char* name, const char* doc, PyObject* bases) {
  const std::string qualified = std::string("coolinggen.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (!cls) throw py::error_already_set();
  m.add_object(name, py::handle(cls));  // steals nothing: add_object increments
  return cls;
}

PyObject* bases(std::initializer_list<PyObject*> classes) {
  PyObject* t = PyTuple_New(static_cast<Py_ssize_t>(classes.size()));
  Py_ssize_t i = 0;
  for (PyObject* c : classes) {
    Py_INCREF(c);
    PyTuple_SET_ITEM(t, i++, c);
  }
  return t;
}

void raise_config_error(const std::string& message) {
  py::object error = py::reinterpret_borrow<py::object>(g_config_error)(message);
  const std::optional<std::string> field = config_error_field(message);
  error.attr("field") = field ? py::object(py::str(*field)) : py::object(py::none());
  PyErr_SetObject(g_config_error, error.ptr());
}

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const config::ConfigError& e) {
    raise_config_error(e.what());
  } catch (const Cancelled& e) {
    PyErr_SetString(g_cancelled, e.what());
  } catch (const CancelledError& e) {
    PyErr_SetString(g_cancelled, e.what());
  } catch (const FeatureFailureError& e) {
    PyErr_SetString(g_feature_failure, e.what());
  } catch (const io::ExportError& e) {
    PyErr_SetString(g_output_error, e.what());
  } catch (const InvalidGeometry& e) {
    PyErr_SetString(g_geometry_error, e.what());
  } catch (const Error& e) {
    PyErr_SetString(g_error, e.what());
  } catch (const Standard_Failure& e) {
    PyErr_SetString(g_error, (std::string("OCCT: ") + e.GetMessageString()).c_str());
  }
}

}  // namespace

std::optional<std::string> config_error_field(const std::string& m) {
  // identifier ( "." identifier | "[" digits "]" )* followed by ": "
  const auto ident = [&](std::size_t& i) {
    if (i >= m.size() || !(std::isalpha(static_cast<unsigned char>(m[i])) || m[i] == '_')) return false;
    while (i < m.size() && (std::isalnum(static_cast<unsigned char>(m[i])) || m[i] == '_')) ++i;
    return true;
  };
  std::size_t i = 0;
  if (!ident(i)) return std::nullopt;
  while (i < m.size()) {
    if (m[i] == '.') {
      ++i;
      if (!ident(i)) return std::nullopt;
    } else if (m[i] == '[') {
      const std::size_t start = ++i;
      while (i < m.size() && std::isdigit(static_cast<unsigned char>(m[i]))) ++i;
      if (i == start || i >= m.size() || m[i] != ']') return std::nullopt;
      ++i;
    } else {
      break;
    }
  }
  if (m.compare(i, 2, ": ") != 0) return std::nullopt;
  return m.substr(0, i);
}

void bind_errors(py::module_& m) {
  g_error = new_class(m, "Error", "Base class of every CoolingGen error.", PyExc_Exception);
  g_config_error = new_class(m, "ConfigError",
                             "Invalid configuration; .field is the JSON path the message names (or None).", g_error);
  PyObject_SetAttrString(g_config_error, "field", Py_None);
  g_feature_failure = new_class(m, "FeatureFailure", "The model or the solid could not be made.", g_error);
  g_cancelled = new_class(m, "Cancelled", "A build stopped on request (timeout, Ctrl-C, a progress callback).", g_error);
  PyObject* output_bases = bases({g_error, PyExc_OSError});
  g_output_error = new_class(m, "OutputError", "An output file could not be written.", output_bases);
  Py_DECREF(output_bases);
  PyObject* geometry_bases = bases({g_error, PyExc_ValueError});
  g_geometry_error = new_class(m, "GeometryError", "Invalid kernel input (knots, poles, weights, parameters).",
                               geometry_bases);
  Py_DECREF(geometry_bases);
  py::register_exception_translator(translate);
}

}  // namespace cg::python
