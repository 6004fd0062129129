#pragma once
// Checks of the coolant flow network files the build wrote (output format "network", docs/network.md),
// each read with a reader that is not ours: CalculiX (`ccx`) runs network.inp again and its .dat is
// parsed here; the deck's connectivity is read from its *ELEMENT cards; film_holes.csv is compared with
// blade.step read back through OCCT (the holes' cylinders and the uncooled outer wall's surface).
#include <BRepAdaptor_Surface.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gp_Pnt2d.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <gp_Pln.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "acceptance/product_build.hpp"
#include "support/ccx_run.hpp"
#include "brep/step_read_back.hpp"

namespace cg::test {

struct NetworkExpect {
  int holes = 0;        ///< film + showerhead holes (one ORIFICE element each)
  int turnarounds = 0;  ///< bends
  std::vector<std::string> chambers;
  int min_segments = 9;  ///< per chamber
};

/// The deck converges in ccx, conserves mass at every node (1e-6 relative or the .dat's 7 digits), the
/// supply's flow equals the sum of the exits, and it has one element per hole, one bend per turnaround
/// and at least 9 segments per chamber.
inline void check_network_deck(const ProductBuild& b, const NetworkExpect& e) {
  const std::string text = read_text(b.file("network.inp"));
  const DeckRead deck = read_deck(text);
  const CcxRun run = run_ccx(b.file("network.inp"));
  BOOST_TEST_REQUIRE(run.converged, "ccx on network.inp: " << run.log.substr(run.log.size() > 2000 ? run.log.size() - 2000 : 0));
  const NodeBalance bal = node_balance(deck, run);
  const double supply = bal.supply, exits = bal.exits;
  BOOST_TEST(bal.worst <= 1.0, "mass imbalance at a node beyond 1e-6 and the printed digits: relative " << bal.worst_relative);
  BOOST_TEST(supply > 0);
  BOOST_TEST(std::abs(supply - exits) / supply < 1e-6, "supply " << supply << " t/s, exits " << exits);
  BOOST_TEST_MESSAGE("network: largest relative node imbalance " << bal.worst_relative << " (printed digits)");
  // Elements by kind, from the deck's sections and names.
  int holes = 0, bends = 0;
  std::map<std::string, int> segments;
  for (const auto& [id, type] : deck.type) {
    const std::string& n = deck.name.count(id) ? deck.name.at(id) : std::string();
    if (type == "ORIFICE MS_MS" && (n.rfind("film_row_", 0) == 0 || n.rfind("showerhead_", 0) == 0)) ++holes;
    if (type.rfind("RESTRICTOR BEND", 0) == 0) ++bends;
    if (n.find("_seg_") != std::string::npos) ++segments[n.substr(0, n.find("_seg_"))];
  }
  BOOST_TEST(holes == e.holes);
  BOOST_TEST(bends == e.turnarounds);
  for (const std::string& c : e.chambers) BOOST_TEST(segments[c] >= e.min_segments, c << ": " << segments[c] << " segments");
  // The product's own results agree with this run.
  const nlohmann::json res = nlohmann::json::parse(read_text(b.file("network_results.json")));
  BOOST_TEST(res.at("status") == "converged");
  BOOST_TEST(std::abs(res.at("total_mass_flow_kg_s").get<double>() - supply * 1e3) <= 1e-6 * supply * 1e3);
  BOOST_TEST(b.report.at("network").at("status") == "converged");
  // The network stage's share of the build (same run): at most 10 %.
  double total = 0;
  for (const auto& [stage, s] : b.report.at("timings_s").items()) total += s.get<double>();
  const double network = b.report.at("timings_s").at("coolant_network").get<double>();
  BOOST_TEST(network <= 0.1 * total, "coolant_network " << network << " s of " << total << " s");
  BOOST_TEST_MESSAGE("network stage " << network << " s of " << total << " s (" << 100 * network / total << " %)");
}

/// The pin banks in front of the slots: one RESTRICTOR USER element per slot in network.inp, each one's
/// solved total-pressure drop against Metzger's published loss computed here by hand (K = 4 x 0.317
/// Re_D^-0.132 per row, Re_D on the pin diameter and the gap velocity of the solved flow, density from the
/// upstream node's pressure and temperature, incompressible head). Tolerance 1 %: the product re-solves
/// until its K is the solved flow's to 1e-3, the node pressures carry 7 digits (about 1 Pa of drops of
/// 300-900 Pa), the gap's Mach number is about 0.02 (measured worst 0.2 %).
inline void check_pin_banks(const ProductBuild& b, int banks) {
  const DeckRead deck = read_deck(read_text(b.file("network.inp")));
  int in_deck = 0;
  for (const auto& [id, type] : deck.type)
    if (deck.name.count(id) && deck.name.at(id).size() > 5 && deck.name.at(id).substr(deck.name.at(id).size() - 5) == "_pins")
      in_deck += type == "RESTRICTOR USER";
  BOOST_TEST(in_deck == banks);
  const nlohmann::json net = nlohmann::json::parse(read_text(b.file("network.json")));
  const nlohmann::json res = nlohmann::json::parse(read_text(b.file("network_results.json")));
  std::map<std::string, double> flow, pressure, temperature;
  for (const auto& e : res.at("elements")) flow[e.at("name")] = e.at("mass_flow_kg_s");
  for (const auto& n : res.at("nodes")) pressure[n.at("name")] = n.at("total_pressure_pa"), temperature[n.at("name")] = n.at("total_temperature_k");
  const double r_gas = net.at("gas").at("gas_constant_j_kg_k"), mu = net.at("gas").at("viscosity_pa_s");
  int checked = 0;
  double worst = 0;
  for (const auto& e : net.at("elements")) {
    if (e.at("kind") != "pin_bank") continue;
    const auto& pins = e.at("pin_fins");
    const std::string up = e.at("upstream"), down = e.at("downstream");
    const double m = flow.at(e.at("name")), area = pins.at("gap_area_mm2").get<double>() * 1e-6;
    const double rho = pressure.at(up) / (r_gas * temperature.at(up)), v = m / (rho * area);
    const double re_d = rho * v * pins.at("diameter_mm").get<double>() * 1e-3 / mu;
    const double k = pins.at("rows").get<int>() * 4 * 0.317 * std::pow(re_d, -0.132);
    const double hand = k * 0.5 * rho * v * v, solved = pressure.at(up) - pressure.at(down);
    worst = std::max(worst, std::abs(solved - hand) / hand);
    BOOST_TEST(std::abs(solved - hand) <= 0.01 * hand, e.at("name").get<std::string>() << ": ccx " << solved << " Pa, Metzger by hand " << hand << " Pa at Re_D " << re_d);
    ++checked;
  }
  BOOST_TEST(checked == banks);
  BOOST_TEST_MESSAGE("pin banks: worst relative difference of the pressure drop against Metzger by hand " << worst);
}

/// film_holes.csv: one line per hole; every exit centre on the surface of the blade's outer wall
/// (faces blade_wall of blade.step, their untrimmed surfaces: the uncooled wall), every axis parallel to
/// the axis of a cylinder of that hole's faces in blade.step. Then one line per trailing-edge slot (as
/// many as blade.step has te_slot_<nn> names): its inlet and exit centres in the air (outside the blade
/// solid: the chamber, the opening), the exit centre at most half the slot's height (`slot_height`, mm)
/// from that slot's faces.
inline void check_film_holes_csv(const ProductBuild& b, int holes, double slot_height = 0) {
  std::istringstream in(read_text(b.file("film_holes.csv")));
  std::string line;
  std::getline(in, line);
  BOOST_TEST(line.rfind("name,row,chamber,shape,exit_x_mm", 0) == 0);
  const StepReadBack step = read_step_back(b.file("blade.step"));
  BOOST_TEST_REQUIRE(step.ok);
  std::vector<Handle(Geom_Surface)> wall;
  for (auto [it, end] = step.named_faces.equal_range("blade_wall"); it != end; ++it)
    wall.push_back(BRep_Tool::Surface(TopoDS::Face(it->second)));
  BOOST_TEST_REQUIRE(!wall.empty());
  std::set<std::string> slot_names;
  for (const auto& [name, face] : step.named_faces)
    if (name.rfind("te_slot_", 0) == 0) slot_names.insert(name);
  // The blade body: the solid named "blade" (a part with inserts), else the file's first solid.
  TopoDS_Shape blade;
  if (step.named_solids.count("blade")) blade = step.named_solids.at("blade");
  for (std::size_t i = 0; blade.IsNull() && i < step.free_shapes.size(); ++i)
    if (TopExp_Explorer ex(step.free_shapes[i], TopAbs_SOLID); ex.More()) blade = ex.Current();
  BOOST_TEST_REQUIRE(!blade.IsNull());
  int n = 0, slots = 0;
  double worst_wall = 0, worst_axis = 0;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) f.push_back(c);
    BOOST_TEST_REQUIRE(f.size() >= 21u, line);
    const gp_Pnt exit(std::stod(f[4]), std::stod(f[5]), std::stod(f[6]));
    if (f[3] == "slot") {
      ++slots;
      BOOST_TEST(slot_names.count(f[0]) == 1u, line);
      const gp_Pnt inlet(std::stod(f[7]), std::stod(f[8]), std::stod(f[9]));
      for (const gp_Pnt& p : {exit, inlet}) {
        BRepClass3d_SolidClassifier where(blade, p, 1e-7);
        BOOST_TEST((where.State() == TopAbs_OUT), f[0] << ": a centre inside the metal: " << line);
      }
      double d = HUGE_VAL;
      for (auto [it, end] = step.named_faces.equal_range(f[0]); it != end; ++it) {
        BRepExtrema_DistShapeShape ds(BRepBuilderAPI_MakeVertex(exit).Vertex(), it->second);
        if (ds.IsDone()) d = std::min(d, ds.Value());
      }
      BOOST_TEST(d <= 0.5 * slot_height + 1e-6, f[0] << ": exit centre " << d << " mm from its faces");
      continue;
    }
    ++n;
    const gp_Dir axis(std::stod(f[10]), std::stod(f[11]), std::stod(f[12]));
    double d = HUGE_VAL;
    for (const auto& s : wall) {
      GeomAPI_ProjectPointOnSurf p(exit, s);
      if (p.NbPoints() > 0) d = std::min(d, p.LowerDistance());
    }
    worst_wall = std::max(worst_wall, d);
    // The hole's cylinder (the metering part): its axis is the hole's.
    double best = HUGE_VAL;
    for (auto [it, end] = step.named_faces.equal_range(f[0]); it != end; ++it) {
      const BRepAdaptor_Surface s(TopoDS::Face(it->second));
      if (s.GetType() == GeomAbs_Cylinder) best = std::min(best, gp_Vec(s.Cylinder().Axis().Direction()).Crossed(gp_Vec(axis)).Magnitude());
    }
    worst_axis = std::max(worst_axis, best);
  }
  BOOST_TEST(n == holes);
  BOOST_TEST(slots == static_cast<int>(slot_names.size()));
  BOOST_TEST(worst_wall < 1e-6, "largest distance of an exit centre from the outer wall " << worst_wall << " mm");
  BOOST_TEST(worst_axis < 1e-6, "largest sine between a hole's axis and its cylinder's " << worst_axis);
}

/// A plane section of one solid of blade.step as closed polygons: the edges of BRepAlgoAPI_Section
/// (plane z = const), each named by the blade.step face it lies on (HasAncestorFaceOn1), sampled every
/// ~0.02 mm. The edges on an opening's faces (film_row_*, showerhead_*, te_slot_*) are left out and the
/// wall is closed across the opening by a straight chord between the two free ends on faces of the same
/// name (the designed wall; the chord differs from the wall's curve by its sagitta, ~1e-2 mm^2 per
/// opening of ~1 mm, 1e-5 of a C3X chamber).
struct SectionPolygon {
  std::vector<gp_Pnt2d> points;
  std::set<std::string> faces;  ///< names of the faces its edges lie on
  double area = 0;              ///< unsigned, mm^2
};

inline bool is_opening_name(const std::string& n) {
  return n.rfind("film_row_", 0) == 0 || n.rfind("showerhead_", 0) == 0 || n.rfind("te_slot_", 0) == 0;
}

inline std::vector<SectionPolygon> closed_plane_section(const TopoDS_Shape& solid, const StepReadBack& step, double z) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  std::vector<std::string> face_name(static_cast<std::size_t>(faces.Extent()) + 1);
  for (const auto& [name, f] : step.named_faces)
    if (const int i = faces.FindIndex(f); i > 0) face_name[static_cast<std::size_t>(i)] = name;
  BRepAlgoAPI_Section sec(solid, gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), false);
  sec.ComputePCurveOn1(Standard_False);
  sec.Approximation(Standard_False);
  sec.Build();
  // Wall runs: sampled edges with their face's name.
  struct Run {
    std::vector<gp_Pnt2d> p;
    std::string name;
  };
  std::vector<Run> runs;
  for (TopExp_Explorer e(sec.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    TopoDS_Shape f;
    std::string name;
    if (sec.HasAncestorFaceOn1(edge, f)) name = face_name[static_cast<std::size_t>(faces.FindIndex(f))];
    if (is_opening_name(name)) continue;
    BRepAdaptor_Curve c(edge);
    const int n = std::max(8, static_cast<int>(GCPnts_AbscissaPoint::Length(c) / 0.02));
    Run r{{}, name};
    for (int k = 0; k <= n; ++k) {
      const gp_Pnt q = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / n);
      r.p.emplace_back(q.X(), q.Y());
    }
    runs.push_back(std::move(r));
  }
  // Chain runs end to end (shared vertices), then close across openings (same face name, nearest).
  std::vector<SectionPolygon> out;
  std::vector<bool> used(runs.size(), false);
  for (std::size_t start = 0; start < runs.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    SectionPolygon poly;
    poly.points = runs[start].p;
    poly.faces.insert(runs[start].name);
    std::string last_name = runs[start].name;
    constexpr double joined = 1e-4;  // mm: ends of edges that share a vertex
    for (;;) {
      const gp_Pnt2d tail = poly.points.back();
      if (poly.points.size() > 2 && tail.Distance(poly.points.front()) < joined) break;
      // The run that continues here; else across an opening the nearest free end on a face of the same
      // name, unless the polygon's own start is nearer (then it closes across that opening).
      std::size_t next = runs.size();
      bool reverse = false;
      double best = HUGE_VAL;
      for (int pass = 0; pass < 2 && next == runs.size(); ++pass)
        for (std::size_t k = 0; k < runs.size(); ++k) {
          if (used[k] || (pass == 1 && runs[k].name != last_name)) continue;
          for (bool rev : {false, true}) {
            const double d = tail.Distance(rev ? runs[k].p.back() : runs[k].p.front());
            if (d < best && (pass == 1 || d < joined)) best = d, next = k, reverse = rev;
          }
        }
      if (next == runs.size()) break;
      if (best >= joined && runs[start].name == last_name && tail.Distance(poly.points.front()) <= best) break;
      used[next] = true;
      std::vector<gp_Pnt2d> p = runs[next].p;
      if (reverse) std::reverse(p.begin(), p.end());
      poly.points.insert(poly.points.end(), p.begin() + (best < joined ? 1 : 0), p.end());
      poly.faces.insert(runs[next].name);
      last_name = runs[next].name;
    }
    double a = 0;
    for (std::size_t k = 0; k < poly.points.size(); ++k) {
      const gp_Pnt2d& u = poly.points[k];
      const gp_Pnt2d& v = poly.points[(k + 1) % poly.points.size()];
      a += u.X() * v.Y() - v.X() * u.Y();
    }
    poly.area = std::abs(a) / 2;
    out.push_back(std::move(poly));
  }
  return out;
}

/// Straight vanes: the area of every segment end station in network.json (end stations at the end walls
/// included) against blade.step read back through OCCT: the plane section z = span * span_length of the
/// blade solid (closed_plane_section: walls closed across the holes that cross it), the cavity loop of
/// the station's chamber (the loop on faces chamber_<k>_wall), minus the insert's metal in that plane
/// (BRepAlgoAPI_Common of the plane with the insert solid) when the insert sits in it; 1e-3 relative.
inline void check_straight_station_areas(const ProductBuild& b, double span_length) {
  const nlohmann::json net = nlohmann::json::parse(read_text(b.file("network.json")));
  const StepReadBack step = read_step_back(b.file("blade.step"));
  BOOST_TEST_REQUIRE(step.ok);
  BOOST_TEST_REQUIRE(step.named_solids.count("blade"));
  std::map<std::pair<std::string, double>, double> stations;
  for (const auto& e : net.at("elements")) {
    if (e.at("kind") != "segment") continue;
    stations[{e.at("chamber").get<std::string>(), e.at("span_in").get<double>()}] = e.at("area_in_mm2").get<double>();
    stations[{e.at("chamber").get<std::string>(), e.at("span_out").get<double>()}] = e.at("area_out_mm2").get<double>();
  }
  int compared = 0;
  double worst = 0;
  for (const auto& [key, area] : stations) {
    const auto& [chamber, span] = key;
    const double z = span * span_length;
    const TopoDS_Face plane = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), -1e3, 1e3, -1e3, 1e3);
    double cavity = 0;
    int loops = 0;
    gp_Pnt2d lo(HUGE_VAL, HUGE_VAL), hi(-HUGE_VAL, -HUGE_VAL);
    for (const SectionPolygon& poly : closed_plane_section(step.named_solids.at("blade"), step, z))
      if (poly.faces.count(chamber + "_wall")) {
        cavity += poly.area;
        ++loops;
        for (const gp_Pnt2d& q : poly.points)
          lo.SetCoord(std::min(lo.X(), q.X()), std::min(lo.Y(), q.Y())), hi.SetCoord(std::max(hi.X(), q.X()), std::max(hi.Y(), q.Y()));
      }
    BOOST_TEST_REQUIRE(loops > 0, chamber << " at z = " << z << ": no loop on " << chamber << "_wall");
    for (const auto& [name, solid] : step.named_solids) {
      if (name == "blade") continue;
      GProp_GProps g;
      BRepGProp::SurfaceProperties(BRepAlgoAPI_Common(plane, solid).Shape(), g);
      const gp_Pnt c = g.CentreOfMass();
      if (std::abs(g.Mass()) > 0 && c.X() > lo.X() && c.X() < hi.X() && c.Y() > lo.Y() && c.Y() < hi.Y()) cavity -= std::abs(g.Mass());
    }
    const double rel = std::abs(cavity - area) / area;
    BOOST_TEST(rel < 1e-3, chamber << " at span " << span << ": network " << area << " mm^2, OCCT " << cavity);
    worst = std::max(worst, rel);
    ++compared;
  }
  BOOST_TEST(compared >= 2 * 10, compared << " stations compared");
  BOOST_TEST_MESSAGE("station areas vs OCCT sections of blade.step: " << compared << " compared, worst relative " << worst);
}

}  // namespace cg::test
