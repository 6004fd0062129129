#include "src/brep/named_shape.hpp"

#include <cctype>

namespace cg::brep {

std::string feature_kind(const std::string& face_name) {
  // Words are separated by '_'; the kind ends before the first word that starts with a digit.
  std::string kind;
  std::size_t start = 0;
  while (start < face_name.size()) {
    std::size_t end = face_name.find('_', start);
    if (end == std::string::npos) end = face_name.size();
    if (end > start && std::isdigit(static_cast<unsigned char>(face_name[start]))) break;
    if (!kind.empty()) kind += '_';
    kind += face_name.substr(start, end - start);
    start = end + 1;
  }
  return kind.empty() ? face_name : kind;
}

std::map<std::string, int> count_face_names(const NamedShape& shape) {
  std::map<std::string, int> counts;
  for (const NamedFace& f : shape.faces) ++counts[f.name];
  return counts;
}

}  // namespace cg::brep
