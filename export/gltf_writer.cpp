#include "export/gltf_writer.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Message_ProgressRange.hxx>
#include <NCollection_DataMap.hxx>
#include <Poly_Triangulation.hxx>
#include <RWGltf_CafWriter.hxx>
#include <RWMesh_CoordinateSystem.hxx>
#include <TColStd_IndexedDataMapOfStringString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_VisMaterial.hxx>
#include <XCAFDoc_VisMaterialTool.hxx>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

#include "export/atomic_file.hpp"
#include "export/feature_style.hpp"
#include "export/part_document.hpp"
#include "export/version.hpp"
#include "src/brep/solid_integrals.hpp"

namespace cg::io {
namespace fs = std::filesystem;
namespace {

// A copy of every body (shapes and face names), so the viewing mesh never lands on the shared part.
brep::Part copy_part(const brep::Part& part) {
  brep::Part out;
  for (const brep::NamedBody& b : part) {
    BRepBuilderAPI_Copy copier(b.geometry.shape, /*copyGeom=*/false, /*copyMesh=*/false);
    brep::NamedBody c{b.name, {copier.Shape(), {}}};
    for (const brep::NamedFace& f : b.geometry.faces) c.geometry.faces.push_back({TopoDS::Face(copier.ModifiedShape(f.face)), f.name});
    out.push_back(std::move(c));
  }
  return out;
}

// One PBR material per feature kind (metallic 0: glTF's default 1 shows plain colours dark), on every
// face of that kind.
void set_kind_materials(const PartDocument& doc, const brep::Part& part) {
  const Handle(XCAFDoc_VisMaterialTool) tool = XCAFDoc_DocumentTool::VisMaterialTool(doc.document()->Main());
  std::map<std::string, TDF_Label> of_kind;
  for (const brep::NamedBody& b : part)
    for (const brep::NamedFace& f : b.geometry.faces) {
      const std::string kind = brep::feature_kind(f.name);
      auto it = of_kind.find(kind);
      if (it == of_kind.end()) {
        Handle(XCAFDoc_VisMaterial) m = new XCAFDoc_VisMaterial();
        XCAFDoc_VisMaterialPBR pbr;
        const Colour c = kind_colour(kind);
        pbr.BaseColor = Quantity_ColorRGBA(Quantity_Color(c[0], c[1], c[2], Quantity_TOC_sRGB));
        pbr.Metallic = 0.0f;
        pbr.Roughness = 0.6f;
        m->SetPbrMaterial(pbr);
        it = of_kind.emplace(kind, tool->AddMaterial(m, TCollection_AsciiString(kind.c_str()))).first;
      }
      if (!tool->SetShapeMaterial(f.face, it->second))
        throw ExportError("glTF: face \"" + f.name + "\" of body \"" + b.name + "\" is not in the document");
    }
}

// The faces as RWGltf_CafWriter visits them (the document's compound, TopExp_Explorer order, one
// primitive each), with their names; every face must have triangles (the writer skips those without).
GltfModel face_table(const PartDocument& doc, const brep::Part& copy, const brep::Part& part) {
  struct Owner {
    std::size_t body, face;
  };
  NCollection_DataMap<TopoDS_Shape, Owner, TopTools_ShapeMapHasher> owner;
  for (std::size_t b = 0; b < copy.size(); ++b)
    for (std::size_t f = 0; f < copy[b].geometry.faces.size(); ++f) owner.Bind(copy[b].geometry.faces[f].face, {b, f});
  GltfModel m;
  for (TopExp_Explorer e(doc.compound(), TopAbs_FACE); e.More(); e.Next()) {
    if (!owner.IsBound(e.Current())) throw ExportError("glTF: a face of the part has no name");
    const Owner o = owner.Find(e.Current());
    const brep::NamedFace& named = part[o.body].geometry.faces[o.face];
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(TopoDS::Face(e.Current()), loc);
    if (t.IsNull() || t->NbTriangles() == 0)
      throw ExportError("glTF: face \"" + named.name + "\" of body \"" + part[o.body].name + "\" could not be triangulated");
    m.triangles += static_cast<std::size_t>(t->NbTriangles());
    m.faces.push_back({part[o.body].name, named.name, brep::feature_kind(named.name),
                       brep::integrate_solid(named.face, 1e-6, false, brep::Integrals::Area).area});
  }
  return m;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) throw ExportError("glTF: cannot read back " + file.string());
  return s.str();
}

// The writer needs a file name: a private one in the temporary directory, removed afterwards.
struct TemporaryFile {
  fs::path path;
  TemporaryFile() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("coolinggen_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".glb");
  }
  ~TemporaryFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

}  // namespace

GltfModel make_gltf(const brep::Part& part, const GltfOptions& options) {
  if (part.empty()) throw ExportError("glTF: the part has no bodies");
  if (!(options.linear_deflection > 0) || !(options.angular_deflection > 0))
    throw ExportError("glTF: triangulation deflections must be > 0");
  Bnd_Box box;
  for (const brep::NamedBody& b : part) BRepBndLib::Add(b.geometry.shape, box);
  const double deflection =
      std::max(options.linear_deflection, box.IsVoid() ? 0.0 : kGltfRelativeDeflection * std::sqrt(box.SquareExtent()));
  const brep::Part copy = copy_part(part);
  for (const brep::NamedBody& b : copy) {
    BRepMesh_IncrementalMesh(b.geometry.shape, deflection, false, options.angular_deflection, true);
    // A face small against the deflection can come out without triangles: once more, finer.
    for (const brep::NamedFace& f : b.geometry.faces) {
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(f.face, loc);
      if (t.IsNull() || t->NbTriangles() == 0) BRepMesh_IncrementalMesh(f.face, deflection / 20, false, options.angular_deflection / 2);
    }
  }
  const PartDocument doc(copy, options.product_name);
  set_kind_materials(doc, copy);
  GltfModel model = face_table(doc, copy, part);
  model.deflection = deflection;

  const TemporaryFile tmp;
  RWGltf_CafWriter writer(TCollection_AsciiString(tmp.path.string().c_str()), /*isBinary=*/true);
  writer.ChangeCoordinateSystemConverter().SetInputLengthUnit(0.001);  // mm -> m
  writer.ChangeCoordinateSystemConverter().SetInputCoordinateSystem(RWMesh_CoordinateSystem_Zup);
  writer.SetMergeFaces(false);  // one primitive per face: the face table maps them
  TColStd_IndexedDataMapOfStringString info;
  info.Add("generator", TCollection_AsciiString((std::string(kToolName) + " " + tool_version()).c_str()));
  if (!writer.Perform(doc.document(), info, Message_ProgressRange())) throw ExportError("glTF: the writer failed");
  model.glb = read_bytes(tmp.path);
  return model;
}

void write_glb(const fs::path& file, const GltfModel& model) {
  write_atomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(model.glb.data(), static_cast<std::streamsize>(model.glb.size()));
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

}  // namespace cg::io
