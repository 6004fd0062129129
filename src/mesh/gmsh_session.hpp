#pragma once
// One gmsh job (gmsh is a process-wide singleton) and the way its errors reach us.
//
// gmsh 4.8's API throws the message of any error as a std::string (General.AbortOnError 2), also from
// inside its OpenMP loops (2D meshing runs faces in parallel), where nothing can catch it and the
// process would terminate. So meshing steps run through generate(), with General.AbortOnError 1
// (errors stop meshing and are logged, not thrown) and the first error logged becomes a MeshError.
// Only errors are logged (General.Verbosity 1): gmsh's logger appends to one vector without a lock, and
// info messages come from every meshing thread.
#include <string>

namespace cg::mesh {

/// Initialises gmsh for one job; finalises on every exit path.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// gmsh::model::mesh::generate(dim); throws MeshError("mesh: <step>: <gmsh's error>") when gmsh logged
/// an error (in this step or before).
void generate(int dim, const std::string& step);

}  // namespace cg::mesh
