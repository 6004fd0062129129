#include "src/cli/exit_codes.hpp"

#include <Standard_Failure.hxx>

#include <iostream>

#include "export/atomic_file.hpp"
#include "src/config/config_error.hpp"
#include "src/core/progress.hpp"

namespace cg::cli {

int error_exit(int code, std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "coolinggen: error: " << message << "\n";
  return code;
}

int run_command(const std::function<int()>& command) {
  try {
    return command();
  } catch (const config::ConfigError& e) {
    return error_exit(kBadConfig, e.what());
  } catch (const io::ExportError& e) {
    return error_exit(kOutputFailure, e.what());
  } catch (const Stopped& e) {
    return error_exit(kStopped, e.what());
  } catch (const Cancelled& e) {  // a command that did not add the reason
    return error_exit(kStopped, e.what());
  } catch (const Error& e) {  // InvalidGeometry / AlgorithmFailure from the model or solid, ChecksFailed
    return error_exit(kModelFailure, std::string(kToolFailure) + e.what());
  } catch (const Standard_Failure& e) {
    return error_exit(kUnexpected, std::string("OCCT: ") + e.GetMessageString());
  } catch (const std::exception& e) {
    return error_exit(kUnexpected, e.what());
  }
}

}  // namespace cg::cli
