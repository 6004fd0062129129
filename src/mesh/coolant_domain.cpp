#include "src/mesh/coolant_domain.hpp"

#include <BOPAlgo_Builder.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRep_Builder.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopExp.hxx>

#include "src/brep/solid_integrals.hpp"

namespace cg::mesh {
namespace {

using NameMap = NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher>;

// Binds the names of `faces` to what they became in an operation with history (`modified`,
// `deleted`): a kept face keeps its name, each split piece gets it. First binding wins, so bind the
// preferred names (metal side) first.
template <class Op>
void bind_history(Op& op, const std::vector<brep::NamedFace>& faces, const std::string& prefix, NameMap& names) {
  for (const brep::NamedFace& f : faces) {
    if (op.IsDeleted(f.face)) continue;
    const TopTools_ListOfShape& mod = op.Modified(f.face);
    if (mod.IsEmpty()) {
      if (!names.IsBound(f.face)) names.Bind(f.face, prefix + f.name);
    }
    for (const TopoDS_Shape& m : mod)
      if (!names.IsBound(m)) names.Bind(m, prefix + f.name);
  }
}

std::vector<brep::NamedFace> name_faces(const TopoDS_Shape& shape, const NameMap& names, const char* what) {
  std::vector<brep::NamedFace> out;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const std::string* n = names.Seek(faces(i));
    if (!n) throw MeshError(std::string(what) + ": a face has no name in the boolean history");
    out.push_back({TopoDS::Face(faces(i)), *n});
  }
  return out;
}

}  // namespace

CoolantDomain coolant_domain(const brep::Part& part, const TopoDS_Shape& uncooled,
                             const std::vector<brep::NamedFace>& uncooled_faces) {
  if (part.empty()) throw MeshError("coolant domain: the part has no bodies");
  if (uncooled.IsNull()) throw MeshError("coolant domain: no uncooled blade solid given");
  CoolantDomain c;
  c.removed_volume = brep::volume_of(uncooled) - brep::volume_of(part[0].geometry.shape);
  TopTools_ListOfShape args, tools;
  args.Append(uncooled);
  for (const brep::NamedBody& b : part) tools.Append(b.geometry.shape);
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tools);
  cut.SetRunParallel(true);
  cut.Build();
  if (!cut.IsDone() || cut.HasErrors()) throw MeshError("coolant domain: the cut uncooled - blade failed");
  BRep_Builder bb;
  TopoDS_Compound solids;
  bb.MakeCompound(solids);
  for (TopExp_Explorer e(cut.Shape(), TopAbs_SOLID); e.More(); e.Next()) {
    bb.Add(solids, e.Current());
    ++c.solids;
  }
  if (c.solids == 0) return c;  // no cavities: an uncooled blade
  NameMap names;
  for (const brep::NamedBody& b : part) bind_history(cut, b.geometry.faces, "", names);  // interfaces: metal names
  if (!uncooled_faces.empty()) {
    bind_history(cut, uncooled_faces, "coolant_opening_", names);
  } else {  // unnamed envelope: every opening is "coolant_opening"
    std::vector<brep::NamedFace> envelope;
    for (TopExp_Explorer e(uncooled, TopAbs_FACE); e.More(); e.Next()) envelope.push_back({TopoDS::Face(e.Current()), ""});
    bind_history(cut, envelope, "coolant_opening", names);
  }
  c.shape = solids;
  c.faces = name_faces(solids, names, "coolant domain");
  c.volume = brep::volume_of(solids);
  return c;
}

ConformalDomains conformal_domains(const brep::Part& part, const CoolantDomain& coolant) {
  if (part.size() + (coolant.shape.IsNull() ? 0 : 1) == 1) {
    // One region (an uncooled blade, or the coolant alone): nothing to share, no fuse needed.
    ConformalDomains d;
    BRep_Builder bb;
    bb.MakeCompound(d.compound);
    const bool fluid = part.empty();
    const TopoDS_Shape& s = fluid ? coolant.shape : part.front().geometry.shape;
    Region r{fluid ? "coolant" : part.front().name, fluid, {}};
    for (TopExp_Explorer e(s, TopAbs_SOLID); e.More(); e.Next()) {
      r.solids.push_back(e.Current());
      bb.Add(d.compound, e.Current());
    }
    d.regions.push_back(std::move(r));
    d.faces = fluid ? coolant.faces : part.front().geometry.faces;
    return d;
  }
  BOPAlgo_Builder gf;
  for (const brep::NamedBody& b : part) gf.AddArgument(b.geometry.shape);
  if (!coolant.shape.IsNull()) gf.AddArgument(coolant.shape);
  gf.SetRunParallel(true);
  gf.SetNonDestructive(true);
  gf.Perform();
  if (gf.HasErrors()) throw MeshError("meshing: the general fuse of metal and coolant failed");
  ConformalDomains d;
  NameMap names;
  for (const brep::NamedBody& b : part) bind_history(gf, b.geometry.faces, "", names);
  if (!coolant.shape.IsNull()) bind_history(gf, coolant.faces, "", names);
  BRep_Builder bb;
  bb.MakeCompound(d.compound);
  auto add_region = [&](const std::string& name, bool fluid, const TopoDS_Shape& input) {
    Region r{name, fluid, {}};
    for (TopExp_Explorer e(input, TopAbs_SOLID); e.More(); e.Next()) {
      const TopTools_ListOfShape& mod = gf.Modified(e.Current());
      if (mod.IsEmpty()) {
        r.solids.push_back(e.Current());
      } else {
        for (const TopoDS_Shape& m : mod) r.solids.push_back(m);
      }
    }
    for (const TopoDS_Shape& s : r.solids) bb.Add(d.compound, s);
    d.regions.push_back(std::move(r));
  };
  for (const brep::NamedBody& b : part) add_region(b.name, false, b.geometry.shape);
  if (!coolant.shape.IsNull()) add_region("coolant", true, coolant.shape);
  d.faces = name_faces(d.compound, names, "metal/coolant fuse");
  return d;
}

}  // namespace cg::mesh
