#include "src/pipeline/build_result.hpp"

namespace cg::pipeline {

bool BuildResult::valid() const {
  if (checks.empty() || checks.size() != part.size()) return false;
  for (const brep::SolidCheck& c : checks)
    if (!c.all_passed()) return false;
  return true;
}

std::string BuildResult::failed_checks() const {
  std::string s;
  for (std::size_t i = 0; i < checks.size() && i < part.size(); ++i)
    if (!checks[i].all_passed()) s += (s.empty() ? "" : "; ") + part[i].name + ": " + checks[i].failed_names();
  if (checks.size() != part.size()) s += (s.empty() ? "" : "; ") + std::string("not every body was checked");
  return s;
}

}  // namespace cg::pipeline
