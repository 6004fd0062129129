#include "export/grid_vtk.hpp"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridWriter.h>

#include <algorithm>
#include <fstream>

#include "export/atomic_file.hpp"
#include "src/grid/grid_quality.hpp"

namespace cg::io {

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

}  // namespace

void write_vts(const std::filesystem::path& file, const grid::Block& b, int block_index, double z) {
  vtkNew<vtkStructuredGrid> sg;
  sg->SetDimensions(b.ni + 1, b.nj + 1, 1);
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(b.nodes.size()));
  for (std::size_t k = 0; k < b.nodes.size(); ++k)
    pts->SetPoint(static_cast<vtkIdType>(k), b.nodes[k].x(), b.nodes[k].y(), z);  // VTK order: i fastest, as ours
  sg->SetPoints(pts);
  vtkNew<vtkDoubleArray> jac;
  jac->SetName("scaled_jacobian");
  jac->SetNumberOfTuples(b.cells());
  vtkNew<vtkIntArray> id;
  id->SetName("block");
  id->SetNumberOfTuples(b.cells());
  for (int j = 0; j < b.nj; ++j)
    for (int i = 0; i < b.ni; ++i) {
      jac->SetValue(j * b.ni + i, grid::cell_scaled_jacobian(b, i, j));
      id->SetValue(j * b.ni + i, block_index);
    }
  sg->GetCellData()->AddArray(jac);
  sg->GetCellData()->AddArray(id);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLStructuredGridWriter> w;
    w->SetFileName(tmp.c_str());
    w->SetInputData(sg);
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    if (w->Write() != 1) throw ExportError("VTK could not write " + tmp.string());
  });
}

std::string vts_file_name(const std::string& stem, const grid::Block& block) { return stem + "_" + block.name + ".vts"; }

void write_vtm_index(const std::filesystem::path& vtm_file, const std::vector<std::pair<std::string, std::string>>& blocks) {
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\">\n  <vtkMultiBlockDataSet>\n";
  for (std::size_t k = 0; k < blocks.size(); ++k)
    xml += "    <DataSet index=\"" + std::to_string(k) + "\" name=\"" + xml_escape(blocks[k].first) + "\" file=\"" +
           xml_escape(blocks[k].second) + "\"/>\n";
  xml += "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  write_atomically(vtm_file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp);
    out << xml;
    if (!out) throw ExportError("write error on " + tmp.string());
  });
}

std::vector<std::filesystem::path> write_vtm(const std::filesystem::path& vtm_file, const grid::MultiBlockGrid& grid,
                                             double z) {
  std::vector<std::filesystem::path> files;
  std::vector<std::pair<std::string, std::string>> entries;
  for (std::size_t k = 0; k < grid.blocks.size(); ++k) {
    const grid::Block& b = grid.blocks[k];
    const std::string name = vts_file_name(vtm_file.stem().string(), b);
    write_vts(vtm_file.parent_path() / name, b, static_cast<int>(k), z);
    files.push_back(vtm_file.parent_path() / name);
    entries.emplace_back(b.name, name);
  }
  write_vtm_index(vtm_file, entries);
  files.push_back(vtm_file);
  return files;
}

}  // namespace cg::io
