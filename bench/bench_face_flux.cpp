// bench_face_flux: the volume flux 1/3 * integral of (x - c) . n dA over every face of a cooled blade,
// ours (src/brep/face_flux) against BRepGProp_Vinert on the same faces at the same relative accuracy,
// with the time ratio, and how far the results agree:
//  - ours with strips along u against ours along v (two independent iterated integrals);
//  - ours against BRepGProp (which leaves the pcurves' gaps at the vertices open, and starts its strips
//    at the face's lowest u: on faces whose pcurves meet only within tolerance the two differ by the
//    gaps' contribution, ~1e-7 relative after OCCT booleans);
//  - the solid's volume (sum over its faces).
//
//   bench_face_flux             the built-in example (cooled HPT blade with film holes), built first
//   bench_face_flux --quick     a B-spline plate with 16 oblique holes (OCCT Cut; the CI smoke run)
//   bench_face_flux FILE.brep   the faces of a B-rep file
// Exits 1 when the u and v strips differ by more than 1e-9 or ours and BRepGProp by more than 1e-5 on a
// face (relative to max(|flux|, 1 mm^3)).
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "src/brep/face_flux.hpp"
#include "src/config/builtin_example.hpp"
#include "src/pipeline/build.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// 40 x 40 x 4 mm plate, its faces B-splines, with 4 x 4 oblique holes of radius 0.7 cut by OCCT.
TopoDS_Shape drilled_plate() {
  TopTools_ListOfShape args, tools;
  args.Append(BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeBox(40, 40, 4).Shape(), true).Shape());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5 + 10.0 * i, 5 + 10.0 * j, -1), gp_Dir(0.1 * i, 0.05 * j, 1)), 0.7, 6).Shape());
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tools);
  cut.Build();
  return cut.IsDone() ? cut.Shape() : TopoDS_Shape();
}

}  // namespace

int main(int argc, char** argv) {
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
  TopoDS_Shape shape;
  std::string what;
  try {
    if (argc > 1 && std::string(argv[1]) == "--quick") {
      shape = drilled_plate();
      what = "B-spline plate with 16 oblique holes";
    } else if (argc > 1) {
      BRep_Builder b;
      if (!BRepTools::Read(shape, argv[1], b)) {
        std::fprintf(stderr, "bench_face_flux: cannot read %s\n", argv[1]);
        return 1;
      }
      what = argv[1];
    } else {
      const cg::pipeline::BuildResult r = cg::pipeline::run_build(cg::config::builtin_example_config());
      shape = r.part.front().geometry.shape;
      what = "built-in example (cooled, film holes)";
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_face_flux: %s\n", e.what());
    return 1;
  }
  constexpr double eps = 1e-9;
  const gp_Pnt c(1, 2, 3);
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) faces.push_back(TopoDS::Face(e.Current()));
  double t_ours = 0, t_occt = 0, sum_ours = 0, sum_occt = 0, worst_uv = 0, worst_occt = 0;
  int fallback = 0;
  for (const TopoDS_Face& f : faces) {
    auto t0 = Clock::now();
    const cg::brep::FaceFlux o = cg::brep::face_volume_flux(f, c, eps);
    t_ours += since(t0);
    t0 = Clock::now();
    BRepGProp_Face bf(f);
    BRepGProp_Domain bd(f);
    BRepGProp_Vinert g;
    g.SetLocation(c);
    g.Perform(bf, bd, eps);
    t_occt += since(t0);
    const double u = cg::brep::face_volume_flux(f, c, eps, cg::brep::StripDirection::U).value;
    const double v = cg::brep::face_volume_flux(f, c, eps, cg::brep::StripDirection::V).value;
    // Relative to the face's flux, or 1 mm^3 for faces whose flux nearly cancels.
    const double scale = std::max(1.0, std::abs(g.Mass()));
    worst_uv = std::max(worst_uv, std::abs(u - v) / scale);
    worst_occt = std::max(worst_occt, std::abs(o.value - g.Mass()) / scale);
    sum_ours += o.value;
    sum_occt += g.Mass();
    if (!o.ours) ++fallback;
  }
  std::printf("%s: %zu faces (%d by BRepGProp), relative accuracy %.0e\n", what.c_str(), faces.size(), fallback, eps);
  std::printf("  face flux: ours %.3f s, BRepGProp_Vinert %.3f s, ratio %.1fx\n", t_ours, t_occt, t_occt / t_ours);
  std::printf("  largest difference per face (relative to max(|flux|, 1 mm^3)): ours u vs v strips %.1e, ours vs BRepGProp %.1e\n",
              worst_uv, worst_occt);
  std::printf("  volume: ours %.6f mm^3, BRepGProp %.6f mm^3 (relative difference %.1e)\n", sum_ours, sum_occt,
              std::abs(sum_ours - sum_occt) / std::abs(sum_occt));
  const bool ok = worst_uv <= 1e-9 && worst_occt <= 1e-5 && !faces.empty();
  if (!ok) std::printf("  FAILED: a face's flux disagrees beyond the limits (u vs v 1e-9, BRepGProp 1e-5)\n");
  return ok ? 0 : 1;
}
