#include "src/brep/boolean/boolean_naming.hpp"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace cg::features {

NamingResult name_result(const BooleanRun& run, const brep::NamedShape& part, const std::vector<const brep::NamedShape*>& tools) {
  NamingResult r;
  r.shape.shape = run.result;
  TopTools_IndexedMapOfShape faces;  // orientation-blind (IsSame)
  TopExp::MapShapes(run.result, TopAbs_FACE, faces);
  std::vector<const std::string*> names(static_cast<std::size_t>(faces.Extent()), nullptr);
  const auto name_pieces = [&](const brep::NamedShape& s) {
    for (const brep::NamedFace& f : s.faces)
      for (const TopoDS_Shape& piece : pieces_of(run, f.face)) {
        const int i = faces.FindIndex(piece);
        if (i > 0 && !names[static_cast<std::size_t>(i - 1)]) names[static_cast<std::size_t>(i - 1)] = &f.name;
      }
  };
  name_pieces(part);  // first: a piece shared with a tool face keeps the part's name
  for (const brep::NamedShape* t : tools) name_pieces(*t);
  r.shape.faces.reserve(names.size());
  for (int i = 1; i <= faces.Extent(); ++i) {
    const std::string* n = names[static_cast<std::size_t>(i - 1)];
    if (!n) ++r.unnamed;
    r.shape.faces.push_back({TopoDS::Face(faces(i)), n ? *n : std::string("unnamed")});
  }
  return r;
}

}  // namespace cg::features
