#include "src/cad_import/cad_shape_reader.hpp"

#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>

#include "src/core/error.hpp"

namespace cg::cad_import {
namespace {

TopoDS_Shape transferred(XSControl_Reader& reader, const std::string& path, const char* name) {
  const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
  if (status != IFSelect_RetDone)
    throw InvalidGeometry(path + ": not a " + name + " file OCCT's " + name + " reader can read (status " +
                          std::to_string(static_cast<int>(status)) + ")");
  if (reader.TransferRoots() == 0) throw InvalidGeometry(path + ": no shape could be transferred from this " + name + " file");
  return reader.OneShape();
}

}  // namespace

TopoDS_Shape read_cad_shape(const std::string& path, CadFormat format) {
  TopoDS_Shape shape;
  try {
    if (format == CadFormat::Step) {
      STEPControl_Reader reader;
      shape = transferred(reader, path, "STEP");
    } else {
      IGESControl_Reader reader;
      reader.SetReadVisible(Standard_True);  // blanked entities (construction geometry) are not the blade
      shape = transferred(reader, path, "IGES");
    }
  } catch (const Standard_Failure& e) {
    throw InvalidGeometry(path + ": OCCT's reader failed on this file: " + e.GetMessageString());
  }
  if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_FACE).More())
    throw InvalidGeometry(path + ": the file holds no face (a blade is given as a solid, a shell or a set of surfaces)");
  return shape;
}

}  // namespace cg::cad_import
