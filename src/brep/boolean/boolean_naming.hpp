#pragma once
// Face names of a boolean result from the boolean's history (features/README.md, naming scheme in
// src/brep/named_shape.hpp): every piece of an input face carries that face's name, so a split part
// face keeps its name and a face made from a tool face takes the tool face's name. Where a part face
// and a tool face coincide (one piece shared by both), the part's name wins: the face existed before.
#include <string>
#include <vector>

#include "src/brep/boolean/boolean_run.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct NamingResult {
  brep::NamedShape shape;
  int unnamed = 0;  ///< result faces no input face accounts for (a history failure: must be 0)
};

/// Names every face of run.result from the pieces of the part's and the tools' named faces.
NamingResult name_result(const BooleanRun& run, const brep::NamedShape& part, const std::vector<const brep::NamedShape*>& tools);

}  // namespace cg::features
