#include "export/vtk_writer.hpp"

#include <vtkXMLPolyDataWriter.h>

#include <fstream>

#include "export/atomic_file.hpp"
#include "export/vtk_polydata.hpp"
#include "export/xml_text.hpp"

namespace cg::io {

void write_vtk_piece(const std::filesystem::path& file, const std::string& body_name, const PartTriangles& triangles, int body) {
  const auto pd = body_polydata(triangles, body, body_name);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetFileName(tmp.string().c_str());
    w->SetInputData(pd);
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    if (w->Write() != 1) throw ExportError("cannot write VTK file " + tmp.string());
  });
}

void write_vtk_multiblock(const std::filesystem::path& file, const brep::Part& part, const std::string& stem) {
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        << "  <vtkMultiBlockDataSet>\n";
    for (std::size_t b = 0; b < part.size(); ++b)
      out << "    <DataSet index=\"" << b << "\" name=\"" << xml_escape(part[b].name) << "\" file=\""
          << xml_escape(stem + "_" + part[b].name + ".vtp") << "\"/>\n";
    out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
    out.close();
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

VtkFiles write_vtk(const std::filesystem::path& dir, const std::string& stem, const brep::Part& part,
                   const PartTriangles& triangles) {
  if (part.empty()) throw ExportError("cannot export an empty part (no bodies)");
  VtkFiles files;
  files.multiblock = dir / (stem + ".vtm");
  for (std::size_t b = 0; b < part.size(); ++b) {
    files.pieces.push_back(dir / (stem + "_" + part[b].name + ".vtp"));
    write_vtk_piece(files.pieces.back(), part[b].name, triangles, static_cast<int>(b));
  }
  write_vtk_multiblock(files.multiblock, part, stem);
  return files;
}

}  // namespace cg::io
