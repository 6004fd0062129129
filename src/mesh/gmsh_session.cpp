#include "src/mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <vector>

#include "src/mesh/coolant_domain.hpp"

namespace cg::mesh {

GmshSession::GmshSession() {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 1);
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::finalize();
  } catch (...) {
  }
}

void generate(int dim, const std::string& step) {
  gmsh::option::setNumber("General.AbortOnError", 1);
  gmsh::model::mesh::generate(dim);
  gmsh::option::setNumber("General.AbortOnError", 2);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (const std::string& line : log)
    if (line.rfind("Error", 0) == 0) throw MeshError("mesh: " + step + ": gmsh " + line);
}

}  // namespace cg::mesh
