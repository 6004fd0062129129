#pragma once
// The Python exceptions of the module and the translation of the library's exceptions into them.
//
//   coolinggen.Error              base of everything below (also: any other library error)
//     ConfigError (.field)        config::ConfigError: invalid configuration; .field is the JSON path
//                                 the message starts with ("sections[2].parametric.chord"), else None
//     FeatureFailure              the model or the solid could not be made (InvalidGeometry /
//                                 AlgorithmFailure during a build: what the CLI exits 3 for)
//     Cancelled                   a build stopped on request (timeout, Ctrl-C, a callback that raised)
//     OutputError                 an output file could not be written (io::ExportError; also OSError)
//     GeometryError               invalid kernel input: knots, poles, parameters (also ValueError)
// Messages are the CLI's one-line messages without the "coolinggen: error: " prefix.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "src/core/error.hpp"

namespace cg::python {

/// Thrown inside the bindings to raise coolinggen.FeatureFailure with this message.
class FeatureFailureError : public Error {
 public:
  using Error::Error;
};

/// Thrown inside the bindings to raise coolinggen.Cancelled with this message (reason and place).
class CancelledError : public Error {
 public:
  using Error::Error;
};

/// Creates the exception classes in `m` and registers the translator.
void bind_errors(pybind11::module_& m);

/// The field path a ConfigError message starts with ("flow_path.hub[1][1]: ..."), if any.
std::optional<std::string> config_error_field(const std::string& message);

}  // namespace cg::python
