#include "export/vtk_polydata.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include <unordered_map>

namespace cg::io {
namespace {

vtkSmartPointer<vtkIntArray> int_array(const char* name) {
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  return a;
}

vtkSmartPointer<vtkStringArray> string_table(const char* name, const std::vector<std::string>& values) {
  auto a = vtkSmartPointer<vtkStringArray>::New();
  a->SetName(name);
  for (const auto& v : values) a->InsertNextValue(v);
  return a;
}

}  // namespace

vtkSmartPointer<vtkPolyData> body_polydata(const PartTriangles& t, int body, const std::string& body_name, int kind) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  auto feature = int_array("feature_id"), name = int_array("face_name_id"), face = int_array("face_id");
  std::unordered_map<int, vtkIdType> node_of;  // part node -> polydata point (only the body's nodes)
  for (std::size_t k = 0; k < t.triangles.size(); ++k) {
    if ((body >= 0 && t.body[k] != body) || (kind >= 0 && t.kind_id[k] != kind)) continue;
    vtkIdType ids[3];
    for (int c = 0; c < 3; ++c) {
      const int n = t.triangles[k][static_cast<std::size_t>(c)];
      auto [it, added] = node_of.emplace(n, 0);
      if (added) {
        const auto& p = t.points[static_cast<std::size_t>(n)];
        const auto& q = t.normals[static_cast<std::size_t>(n)];
        it->second = points->InsertNextPoint(p.x(), p.y(), p.z());
        normals->InsertNextTuple3(q.x(), q.y(), q.z());
      }
      ids[c] = it->second;
    }
    polys->InsertNextCell(3, ids);
    feature->InsertNextValue(t.kind_id[k]);
    name->InsertNextValue(t.name_id[k]);
    face->InsertNextValue(t.face[k]);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetPointData()->SetNormals(normals);
  pd->GetCellData()->AddArray(feature);
  pd->GetCellData()->AddArray(name);
  pd->GetCellData()->AddArray(face);
  pd->GetCellData()->SetActiveScalars("feature_id");
  pd->GetFieldData()->AddArray(string_table("feature_kinds", t.table.kinds));
  pd->GetFieldData()->AddArray(string_table("face_names", t.table.names));
  pd->GetFieldData()->AddArray(string_table("body_name", {body_name}));
  return pd;
}

}  // namespace cg::io
