#include "export/preview.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <sstream>

#include "export/atomic_file.hpp"
#include "export/vtk_polydata.hpp"
#include "export/x_display.hpp"

namespace cg::io {
namespace {

// Principal axes of the triangulation's points (largest extent first): the camera looks along the
// smallest (blade thickness), with the largest (span) up.
Eigen::Matrix3d principal_axes(const PartTriangles& t, Eigen::Vector3d& centre, double& radius) {
  centre.setZero();
  for (const auto& p : t.points) centre += p;
  centre /= static_cast<double>(t.points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  radius = 0;
  for (const auto& p : t.points) {
    cov += (p - centre) * (p - centre).transpose();
    radius = std::max(radius, (p - centre).norm());
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  Eigen::Matrix3d axes;  // columns, decreasing eigenvalue
  for (int k = 0; k < 3; ++k) axes.col(k) = es.eigenvectors().col(2 - k);
  return axes;
}

}  // namespace

double kind_opacity(const std::string& kind, double wall_opacity) {
  if (kind == "blade_wall" || kind == "hub" || kind == "casing" || kind == "tip_cap" || kind == "hub_floor") return wall_opacity;
  if (kind == "chamber" || kind == "turnaround") return 0.55;
  return 1.0;
}

PreviewResult write_preview(const std::filesystem::path& file, const PartTriangles& t, const PreviewOptions& o) {
  PreviewResult result;
  if (t.triangles.empty()) throw ExportError("preview: nothing to draw (no triangles)");
  const DisplayStatus display = ensure_x_display();
  if (!display.available) {
    result.message = "preview.png skipped: " + display.message;
    return result;
  }
  result.message = display.message;

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1, 1, 1);
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(12);
  renderer->SetOcclusionRatio(0.0);
  std::vector<std::pair<std::string, Colour>> legend;
  for (std::size_t k = 0; k < t.table.kinds.size(); ++k) {
    const std::string& kind = t.table.kinds[k];
    const auto cells = body_polydata(t, -1, "part", static_cast<int>(k));
    if (cells->GetNumberOfCells() == 0) continue;
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(cells);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    const Colour c = kind_colour(kind);
    actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    actor->GetProperty()->SetSpecular(0.25);
    actor->GetProperty()->SetSpecularPower(30);
    const double opacity = kind_opacity(kind, o.wall_opacity);
    actor->GetProperty()->SetOpacity(opacity);
    renderer->AddActor(actor);
    legend.emplace_back(kind + (opacity < 1 ? " (transparent)" : ""), c);
  }

  Eigen::Vector3d centre;
  double radius = 1;
  const Eigen::Matrix3d axes = principal_axes(t, centre, radius);
  // Look mostly along the thinnest direction, from 35 deg off it towards the chord, 20 deg from above.
  Eigen::Vector3d up = axes.col(0), chord = axes.col(1), thin = axes.col(2);
  if (o.up.norm() > 0) {
    // Up as given; the view direction stays the thinnest principal direction, made normal to up.
    up = o.up.normalized();
    thin = (thin - thin.dot(up) * up).normalized();
    chord = up.cross(thin);
  } else if (up.cwiseAbs().maxCoeff() != up.maxCoeff()) {
    up = -up;  // no hint: the longest axis with its largest component positive (z up for a straight vane)
  }
  const Eigen::Vector3d dir = (thin * std::cos(0.61) + chord * std::sin(0.61) + up * 0.35).normalized();
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetFocalPoint(centre.x(), centre.y(), centre.z());
  const Eigen::Vector3d eye = centre + dir * radius * 4;
  cam->SetPosition(eye.x(), eye.y(), eye.z());
  cam->SetViewUp(up.x(), up.y(), up.z());
  cam->SetViewAngle(30);
  renderer->ResetCamera();
  cam->Zoom(1.15);
  renderer->ResetCameraClippingRange();

  auto add_text = [&](const std::string& text, int x, int y, int size, bool top, const Colour& colour = {0.1, 0.1, 0.1}) {
    auto a = vtkSmartPointer<vtkTextActor>::New();
    a->SetInput(text.c_str());
    a->GetTextProperty()->SetFontSize(size);
    a->GetTextProperty()->SetColor(colour[0], colour[1], colour[2]);
    a->GetTextProperty()->SetBold(size > 20);
    if (top) a->GetTextProperty()->SetVerticalJustificationToTop();
    a->SetDisplayPosition(x, y);
    renderer->AddActor2D(a);
  };
  if (!o.title.empty()) add_text(o.title, 16, o.height - 16, 26, true);
  // Legend, one line per kind in its colour (darkened so light greys stay readable), bottom up.
  for (std::size_t k = 0; k < legend.size(); ++k) {
    const Colour& c = legend[legend.size() - 1 - k].second;
    add_text(legend[legend.size() - 1 - k].first, 16, 16 + 24 * static_cast<int>(k), 18, false,
             {0.75 * c[0], 0.75 * c[1], 0.75 * c[2]});
  }

  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetAlphaBitPlanes(1);
  window->SetMultiSamples(0);  // depth peeling needs no multisampling
  window->SetSize(o.width, o.height);
  window->AddRenderer(renderer);
  window->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    auto w = vtkSmartPointer<vtkPNGWriter>::New();
    w->SetFileName(tmp.string().c_str());
    w->SetInputConnection(grab->GetOutputPort());
    w->Write();
  });
  result.written = true;
  return result;
}

}  // namespace cg::io
