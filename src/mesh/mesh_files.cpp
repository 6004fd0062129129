#include "src/mesh/mesh_files.hpp"

#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <unordered_map>

#include "src/mesh/coolant_domain.hpp"

namespace cg::mesh {
namespace {

// Points used by a set of cells, renumbered densely.
struct Compact {
  vtkSmartPointer<vtkPoints> points = vtkSmartPointer<vtkPoints>::New();
  std::unordered_map<std::size_t, vtkIdType> id;
  vtkIdType operator()(const std::vector<Eigen::Vector3d>& all, std::size_t n) {
    auto [it, added] = id.emplace(n, 0);
    if (added) it->second = points->InsertNextPoint(all[n].x(), all[n].y(), all[n].z());
    return it->second;
  }
};

void write_grid(const FileWriter& files, const std::string& name, vtkUnstructuredGrid* grid) {
  files(name, [&](const std::filesystem::path& target) {
    write_renamed(target, [&](const std::filesystem::path& tmp) {
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetFileName(tmp.string().c_str());
    w->SetInputData(grid);
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    if (w->Write() != 1) throw MeshError("cannot write " + tmp.string());
    });
  });
}

}  // namespace

void write_renamed(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path tmp =
      target.parent_path() / ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + target.extension().string());
  std::error_code ec;
  try {
    write(tmp);
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  if (!std::filesystem::exists(tmp) || std::filesystem::file_size(tmp, ec) == 0) {
    std::filesystem::remove(tmp, ec);
    throw MeshError("writing " + target.string() + " produced no file");
  }
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw MeshError("cannot rename the temporary file to " + target.string());
  }
}

FileWriter directory_writer(const std::filesystem::path& dir) {
  return [dir](const std::string& name, const std::function<void(const std::filesystem::path&)>& writer) { writer(dir / name); };
}

std::vector<std::string> write_vtu_files(const FileWriter& out, const MeshData& data) {
  std::vector<std::string> files;
  for (const auto& b : data.blocks) {
    Compact c;
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->Allocate(static_cast<vtkIdType>(b.tets.size()));
    for (const auto& t : b.tets) {
      const vtkIdType ids[4] = {c(data.points, t[0]), c(data.points, t[1]), c(data.points, t[2]), c(data.points, t[3])};
      grid->InsertNextCell(VTK_TETRA, 4, ids);
    }
    grid->SetPoints(c.points);
    auto name = vtkSmartPointer<vtkStringArray>::New();
    name->SetName("region");
    name->InsertNextValue(b.name);
    grid->GetFieldData()->AddArray(name);
    const std::string file = "mesh_" + b.name + ".vtu";
    write_grid(out, file, grid);
    files.push_back(file);
  }
  Compact c;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->Allocate(static_cast<vtkIdType>(data.triangles.size()));
  auto group = vtkSmartPointer<vtkIntArray>::New();
  group->SetName("group_id");
  for (const auto& t : data.triangles) {
    const vtkIdType ids[3] = {c(data.points, t.nodes[0]), c(data.points, t.nodes[1]), c(data.points, t.nodes[2])};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
    group->InsertNextValue(t.group);
  }
  grid->SetPoints(c.points);
  grid->GetCellData()->AddArray(group);
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("group_names");
  for (const auto& n : data.group_names) names->InsertNextValue(n);
  grid->GetFieldData()->AddArray(names);
  write_grid(out, "mesh_surfaces.vtu", grid);
  files.push_back("mesh_surfaces.vtu");
  return files;
}

}  // namespace cg::mesh
