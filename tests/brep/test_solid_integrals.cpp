#define BOOST_TEST_MODULE solid_integrals
#include <boost/test/unit_test.hpp>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>

#include <cmath>

#include "src/brep/solid_integrals.hpp"
#include "src/core/constants.hpp"

namespace {

using cg::kPi;

// A 40 x 40 x 4 mm plate with n x n through holes of radius r, its faces B-splines (NurbsConvert) so
// the hole loops are B-spline pcurves on B-spline walls, as on a drilled blade.
TopoDS_Shape drilled_plate(int n, double r, bool nurbs) {
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(40, 40, 4).Shape();
  if (nurbs) plate = BRepBuilderAPI_NurbsConvert(plate, true).Shape();
  TopTools_ListOfShape args, tools;
  args.Append(plate);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(4 + 32.0 * i / (n - 1), 4 + 32.0 * j / (n - 1), -1), gp::DZ()), r, 6).Shape());
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tools);
  cut.Build();
  BOOST_REQUIRE(cut.IsDone());
  return cut.Shape();
}

int face_count(const TopoDS_Shape& s) {
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) ++n;
  return n;
}

}  // namespace

// Analytic values: plate minus n^2 cylinders of height 4; area = 2 faces minus the holes' disks,
// the sides, and the holes' walls. Our volume (face_flux.hpp) and the area with its loops split off must
// give BRepGProp's integrals on the whole faces (both at relative accuracy 1e-7; they agree far closer,
// 1e-9 allowed).
BOOST_AUTO_TEST_CASE(drilled_plate_matches_analytic_values_and_brepgprop) {
  const int n = 5;
  const double r = 0.5;
  const double volume = 40.0 * 40 * 4 - n * n * kPi * r * r * 4;
  const double area = 2 * (40.0 * 40 - n * n * kPi * r * r) + 4 * 40 * 4 + n * n * 2 * kPi * r * 4;
  for (bool nurbs : {false, true}) {
    BOOST_TEST_CONTEXT("B-spline faces " << nurbs) {
      const TopoDS_Shape s = drilled_plate(n, r, nurbs);
      const cg::brep::SolidIntegrals in = cg::brep::integrate_solid(s, 1e-7);
      GProp_GProps vp, sp;
      BRepGProp::VolumeProperties(s, vp, 1e-7, true);
      BRepGProp::SurfaceProperties(s, sp, 1e-7);
      // The B-spline plate's hole loops are OCCT's approximated intersection curves (a few 1e-9
      // relative off the analytic shape, measured); the analytic plate's are exact circles.
      const double exact = nurbs ? 1e-8 : 1e-9;
      BOOST_TEST(std::abs(in.volume - volume) <= exact * volume);
      BOOST_TEST(std::abs(in.area - area) <= exact * area);
      BOOST_TEST(std::abs(in.volume - vp.Mass()) <= 1e-9 * volume);
      BOOST_TEST(std::abs(in.area - sp.Mass()) <= 1e-9 * area);
      BOOST_TEST(in.volume_error <= 1e-7 * volume);
      // Every face twice (volume, area), plus the 2 x n^2 hole loops of the top and bottom for the area
      // (the volume's face flux starts each loop's strips at the loop itself: no split needed).
      BOOST_TEST(in.pieces == 2 * face_count(s) + 2 * n * n);
      // Serial: the same sums to the last bit (fixed summation order).
      const cg::brep::SolidIntegrals serial = cg::brep::integrate_solid(s, 1e-7, false);
      BOOST_TEST(serial.volume == in.volume);
      BOOST_TEST(serial.area == in.area);
    }
  }
}

// Faces on periodic surfaces: a tube's cylinders carry seams (not split off), its annular ends an inner
// circle (split off for the area); an open shell has no volume.
BOOST_AUTO_TEST_CASE(tube_and_open_shell) {
  const double R = 5, r = 3, h = 7;
  TopTools_ListOfShape args, tools;
  args.Append(BRepPrimAPI_MakeCylinder(R, h).Shape());
  tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp::DZ()), r, h + 2).Shape());
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tools);
  cut.Build();
  BOOST_REQUIRE(cut.IsDone());
  const cg::brep::SolidIntegrals in = cg::brep::integrate_solid(cut.Shape(), 1e-7);
  BOOST_TEST(std::abs(in.volume - kPi * (R * R - r * r) * h) <= 1e-9 * in.volume);
  BOOST_TEST(std::abs(in.area - (2 * kPi * (R * R - r * r) + 2 * kPi * (R + r) * h)) <= 1e-9 * in.area);
  BOOST_TEST(in.pieces == 2 * 4 + 2);

  TopoDS_Shape face;
  for (TopExp_Explorer e(cut.Shape(), TopAbs_FACE); e.More() && face.IsNull(); e.Next()) face = e.Current();
  const cg::brep::SolidIntegrals open = cg::brep::integrate_solid(face, 1e-7);
  BOOST_TEST(open.volume == 0);
  BOOST_TEST(open.area > 0);
}
