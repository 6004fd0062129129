#include "python/src/config_input.hpp"

#include <cmath>
#include <filesystem>

#include "src/config/json_fields.hpp"
#include "src/core/format.hpp"

namespace py = pybind11;

namespace cg::python {
namespace {

constexpr int kMaxDepth = 100;

std::string type_name(const py::handle& v) { return Py_TYPE(v.ptr())->tp_name; }

std::string where(const std::string& path) { return path.empty() ? "config" : path; }

nlohmann::json from_int(const py::handle& v, const std::string& path) {
  int overflow = 0;
  const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
  if (i == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow == 0) return i;
  if (overflow > 0) {
    const unsigned long long u = PyLong_AsUnsignedLongLong(v.ptr());
    if (!PyErr_Occurred()) return u;
    PyErr_Clear();
  }
  const double d = PyLong_AsDouble(v.ptr());  // a count beyond 2^64: the field's range check refuses it
  if (d == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    config::fail(where(path), "integer out of the range of a double");
  }
  return d;
}

nlohmann::json from_float(double d, const std::string& path) {
  if (!std::isfinite(d)) config::fail(where(path), "must be a finite number, got " + format_number(d));
  return d;
}

nlohmann::json from_str(const py::handle& v, const std::string& path) {
  Py_ssize_t size = 0;
  const char* s = PyUnicode_AsUTF8AndSize(v.ptr(), &size);
  if (!s) {
    PyErr_Clear();
    config::fail(where(path), "string is not valid Unicode (lone surrogate)");
  }
  return std::string(s, static_cast<std::size_t>(size));
}

}  // namespace

nlohmann::json to_json(const py::handle& v, const std::string& path, int depth) {
  if (depth > kMaxDepth) config::fail(where(path), "nested deeper than " + std::to_string(kMaxDepth) + " levels");
  if (v.is_none()) return nullptr;
  if (PyBool_Check(v.ptr())) return v.ptr() == Py_True;
  if (PyLong_Check(v.ptr())) return from_int(v, path);
  if (PyFloat_Check(v.ptr())) return from_float(PyFloat_AS_DOUBLE(v.ptr()), path);
  if (PyUnicode_Check(v.ptr())) return from_str(v, path);
  if (PyDict_Check(v.ptr())) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& item : py::reinterpret_borrow<py::dict>(v)) {
      if (!PyUnicode_Check(item.first.ptr()))
        config::fail(where(path), "keys must be strings, got a key of type " + type_name(item.first));
      const std::string key = from_str(item.first, path).get<std::string>();
      o[key] = to_json(item.second, path.empty() ? key : path + "." + key, depth + 1);
    }
    return o;
  }
  if (PyList_Check(v.ptr()) || PyTuple_Check(v.ptr())) {
    nlohmann::json a = nlohmann::json::array();
    const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
    for (std::size_t i = 0; i < s.size(); ++i)
      a.push_back(to_json(s[i], where(path) + "[" + std::to_string(i) + "]", depth + 1));
    return a;
  }
  // NumPy arrays and scalars (numpy.float32, numpy.int64, ...): their Python equivalent.
  if (py::hasattr(v, "tolist") && py::hasattr(v, "dtype")) return to_json(v.attr("tolist")(), path, depth + 1);
  config::fail(where(path), "must be JSON data (dict, list, str, number, bool or None), got " + type_name(v));
}

config::Config load_config(const py::handle& c) {
  const std::filesystem::path cwd = std::filesystem::current_path();
  // source_file names the input in report.json ("model.source"; empty would say "<built-in example>").
  if (PyDict_Check(c.ptr())) {
    config::Config r = config::parse_config(to_json(c, ""), cwd, "config");
    r.source_file = "<python dict>";
    return r;
  }
  if (PyUnicode_Check(c.ptr())) {
    const std::string s = from_str(c, "").get<std::string>();
    const std::size_t first = s.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && s[first] == '{') {
      config::Config r = config::parse_config_text(s, cwd, "config", "config");
      r.source_file = "<JSON text>";
      return r;
    }
    if (s.empty()) config::fail("config", "empty path");
    return config::load_config_file(s);
  }
  if (py::isinstance(c, py::module_::import("os").attr("PathLike"))) {
    const py::object p = py::module_::import("os").attr("fspath")(c);
    if (!PyUnicode_Check(p.ptr())) config::fail("config", "a path must be a str path, got " + type_name(p));
    return config::load_config_file(from_str(p, "").get<std::string>());
  }
  config::fail("config", "must be a dict, a JSON text or a path (str or os.PathLike), got " + type_name(c));
}

}  // namespace cg::python
