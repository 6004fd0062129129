#include "export/brep_writer.hpp"

#include <BRepTools.hxx>

#include "export/atomic_file.hpp"
#include "export/part_document.hpp"

namespace cg::io {

void write_brep(const std::filesystem::path& file, const brep::Part& part) {
  if (part.empty()) throw ExportError("cannot export an empty part (no bodies)");
  const TopoDS_Compound c = part_compound(part);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    // Without triangulations: the file is the exact geometry, not a cache of some earlier mesh.
    if (!BRepTools::Write(c, tmp.string().c_str(), /*theWithTriangles=*/false, /*theWithNormals=*/false,
                          TopTools_FormatVersion_CURRENT))
      throw ExportError("cannot write BREP file " + tmp.string());
  });
}

}  // namespace cg::io
