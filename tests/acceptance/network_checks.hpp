#pragma once
// Checks of the coolant flow network files the build wrote (output format "network", docs/network.md),
// each read with a reader that is not ours: CalculiX (`ccx`) runs network.inp again and its .dat is
// parsed here; the deck's connectivity is read from its *ELEMENT cards; film_holes.csv is compared with
// blade.step read back through OCCT (the holes' cylinders and the uncooled outer wall's surface).
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <gp_Pln.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "acceptance/product_build.hpp"
#include "brep/step_read_back.hpp"

namespace cg::test {

/// network.inp as CalculiX reads it: element connectivity (upstream, mid, downstream) and the
/// *FLUID SECTION type of each element, element names from the deck's comment lines.
struct DeckRead {
  std::map<int, std::array<int, 3>> elements;
  std::map<int, std::string> type, name;
};

inline DeckRead read_deck(const std::string& text) {
  DeckRead d;
  std::istringstream in(text);
  std::string line, elset;
  std::map<std::string, std::vector<int>> sets;
  bool element_block = false;
  while (std::getline(in, line)) {
    if (line.rfind("** element ", 0) == 0) {
      std::istringstream ls(line.substr(11));
      int id = 0;
      std::string n;
      ls >> id >> n;
      d.name[id] = n;
      continue;
    }
    if (line.rfind("**", 0) == 0) continue;
    if (line.rfind("*", 0) == 0) {
      element_block = line.rfind("*ELEMENT", 0) == 0;
      if (element_block) elset = line.substr(line.find("ELSET=") + 6);
      if (line.rfind("*FLUID SECTION", 0) == 0) {
        const std::size_t a = line.find("ELSET=") + 6, t = line.find("TYPE=") + 5;
        const std::string set = line.substr(a, line.find(',', a) - a), type = line.substr(t, line.find(',', t) - t);
        for (int id : sets[set]) d.type[id] = type;
      }
      continue;
    }
    if (element_block) {
      int id = 0, a = 0, m = 0, b = 0;
      char c = 0;
      std::istringstream ls(line);
      if (ls >> id >> c >> a >> c >> m >> c >> b) {
        d.elements[id] = {a, m, b};
        sets[elset].push_back(id);
      }
    }
  }
  return d;
}

/// ccx run on a copy of the deck: converged, and the .dat's pressures (MPa) and mass flows (t/s).
struct CcxRun {
  bool converged = false;
  std::string log;
  std::map<int, double> pressure, mass_flow;
};

inline CcxRun run_ccx(const std::filesystem::path& deck) {
  CcxRun r;
  TempDir dir("ccx");
  std::filesystem::copy_file(deck, dir.path / "net.inp");
  const std::string cmd = "cd " + q(dir.path) + " && timeout 60 ccx -i net > ccx.out 2>&1";
  const int rc = std::system(cmd.c_str());
  r.log = read_text(dir.path / "ccx.out");
  r.converged = rc == 0 && r.log.find("convergence in gas iteration") != std::string::npos;
  std::istringstream in(read_text(dir.path / "net.dat"));
  std::string line;
  std::map<int, double>* block = nullptr;
  while (std::getline(in, line)) {
    if (line.find("network pressures") != std::string::npos) block = &r.pressure;
    else if (line.find("mass flows") != std::string::npos) block = &r.mass_flow;
    else if (line.find("temperatures") != std::string::npos) block = nullptr;
    else if (block) {
      std::istringstream ls(line);
      int id = 0;
      double v = 0;
      if (ls >> id >> v) (*block)[id] = v;
    }
  }
  return r;
}

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
  // Mass balance at every corner node (node 0 is the outside): 1e-6 of its throughput, or where more the
  // rounding of the .dat's 7 significant digits (half a unit of the last digit of every flow at the node).
  std::map<int, double> in, out, rounding, gross;
  double supply = 0, exits = 0;
  for (const auto& [id, n] : deck.elements) {
    BOOST_TEST_REQUIRE(run.mass_flow.count(n[1]), "mass flow of element " << id);
    const double m = run.mass_flow.at(n[1]);
    const double half_digit = m == 0 ? 0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(m))) - 6);
    if (n[0] != 0) out[n[0]] += m, rounding[n[0]] += half_digit, gross[n[0]] += std::abs(m);
    if (n[2] != 0) in[n[2]] += m, rounding[n[2]] += half_digit, gross[n[2]] += std::abs(m);
    if (n[0] == 0) supply += m;
    if (n[2] == 0) exits += m;
  }
  double worst = 0, worst_relative = 0;
  for (const auto& [node, m_in] : in) {
    // Relative to the node's throughput (half the sum of |flow| of its elements: a hole with backflow
    // brings coolant in through an element drawn as leaving).
    const double m_out = out[node], scale = 0.5 * gross[node];
    const double allowed = std::max(1e-6 * scale, rounding[node]);
    worst = std::max(worst, std::abs(m_in - m_out) / allowed);
    worst_relative = std::max(worst_relative, std::abs(m_in - m_out) / scale);
  }
  BOOST_TEST(worst <= 1.0, "mass imbalance at a node beyond 1e-6 and the printed digits: relative " << worst_relative);
  BOOST_TEST(supply > 0);
  BOOST_TEST(std::abs(supply - exits) / supply < 1e-6, "supply " << supply << " t/s, exits " << exits);
  BOOST_TEST_MESSAGE("network: largest relative node imbalance " << worst_relative << " (printed digits)");
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
}

/// film_holes.csv: one line per hole; every exit centre on the surface of the blade's outer wall
/// (faces blade_wall of blade.step, their untrimmed surfaces: the uncooled wall), every axis parallel to
/// the axis of a cylinder of that hole's faces in blade.step.
inline void check_film_holes_csv(const ProductBuild& b, int holes) {
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
  int n = 0;
  double worst_wall = 0, worst_axis = 0;
  while (std::getline(in, line)) {
    ++n;
    std::vector<std::string> f;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) f.push_back(c);
    BOOST_TEST_REQUIRE(f.size() >= 21u, line);
    const gp_Pnt exit(std::stod(f[4]), std::stod(f[5]), std::stod(f[6]));
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
  BOOST_TEST(worst_wall < 1e-6, "largest distance of an exit centre from the outer wall " << worst_wall << " mm");
  BOOST_TEST(worst_axis < 1e-6, "largest sine between a hole's axis and its cylinder's " << worst_axis);
}

/// Straight vanes: the area of every measured chamber station in network.json against OCCT's plane
/// section of blade.brep at its height (z = span * span_length): the cavity loops of the blade's section,
/// minus the insert's section inside chamber_1. Stations whose plane a hole crosses (film_holes.csv: the
/// hole's z range +- its diameter) join the cavity to the outside in a plain section and are left out;
/// at least `min_compared` stations must be compared (1e-3 relative).
inline void check_straight_station_areas(const ProductBuild& b, double span_length, int min_compared) {
  const nlohmann::json net = nlohmann::json::parse(read_text(b.file("network.json")));
  TopoDS_Shape all;
  BRep_Builder builder;
  BOOST_TEST_REQUIRE(BRepTools::Read(all, b.file("blade.brep").string().c_str(), builder));
  std::vector<TopoDS_Shape> solids;
  for (TopExp_Explorer e(all, TopAbs_SOLID); e.More(); e.Next()) solids.push_back(e.Current());
  BOOST_TEST_REQUIRE(solids.size() == b.bodies.size());
  // z ranges of the holes.
  std::vector<std::pair<double, double>> hole_z;
  std::istringstream csv(read_text(b.file("film_holes.csv")));
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) f.push_back(c);
    const double z0 = std::stod(f[6]), z1 = std::stod(f[9]), d = std::stod(f[13]);
    hole_z.emplace_back(std::min(z0, z1) - d, std::max(z0, z1) + d);
  }
  // Stations: the segments' ends at measured sections (not at an end wall: the segment's other end).
  std::map<std::pair<std::string, double>, double> stations;
  for (const auto& e : net.at("elements")) {
    if (e.at("kind") != "segment") continue;
    stations[{e.at("chamber").get<std::string>(), e.at("span_in").get<double>()}] = e.at("area_in_mm2").get<double>();
    stations[{e.at("chamber").get<std::string>(), e.at("span_out").get<double>()}] = e.at("area_out_mm2").get<double>();
  }
  std::map<std::string, double> lo, hi;  // end stations (end walls) of each chamber
  for (const auto& [key, a] : stations) {
    lo[key.first] = lo.count(key.first) ? std::min(lo[key.first], key.second) : key.second;
    hi[key.first] = hi.count(key.first) ? std::max(hi[key.first], key.second) : key.second;
  }
  int compared = 0;
  double worst = 0;
  for (const auto& [key, area] : stations) {
    const auto& [chamber, span] = key;
    if (span == lo[chamber] || span == hi[chamber]) continue;
    const double z = span * span_length;
    bool crossed = false;
    for (const auto& [z0, z1] : hole_z) crossed = crossed || (z >= z0 && z <= z1);
    if (crossed) continue;
    const TopoDS_Face plane = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), -1e3, 1e3, -1e3, 1e3);
    const TopoDS_Shape metal = BRepAlgoAPI_Common(plane, solids[0]).Shape();
    double insert_area = 0;
    gp_Pnt insert_centre;
    if (solids.size() > 1) {
      const TopoDS_Shape in = BRepAlgoAPI_Common(plane, solids[1]).Shape();
      GProp_GProps g;
      BRepGProp::SurfaceProperties(in, g);
      insert_area = std::abs(g.Mass());
      insert_centre = g.CentreOfMass();
    }
    // Cavities: the inner loops of the blade's section, ordered by x (chamber_1 at the LE, the smaller x).
    std::vector<std::pair<double, double>> cavities;  // centroid x, area
    std::vector<Bnd_Box> boxes;
    for (TopExp_Explorer f(metal, TopAbs_FACE); f.More(); f.Next()) {
      const TopoDS_Face face = TopoDS::Face(f.Current());
      const TopoDS_Wire outer = BRepTools::OuterWire(face);
      for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        if (w.Current().IsSame(outer)) continue;
        const TopoDS_Face loop = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), TopoDS::Wire(w.Current()));
        GProp_GProps g;
        BRepGProp::SurfaceProperties(loop, g);
        Bnd_Box box;
        BRepBndLib::Add(loop, box);
        double a = std::abs(g.Mass());
        if (insert_area > 0 && !box.IsOut(insert_centre)) a -= insert_area;  // the insert sits in this cavity
        cavities.emplace_back(g.CentreOfMass().X(), a);
      }
    }
    std::sort(cavities.begin(), cavities.end());
    const std::size_t k = static_cast<std::size_t>(std::stoi(chamber.substr(chamber.rfind('_') + 1)) - 1);
    BOOST_TEST_REQUIRE(k < cavities.size(), chamber << " at z = " << z << ": " << cavities.size() << " cavities");
    const double rel = std::abs(cavities[k].second - area) / area;
    BOOST_TEST(rel < 1e-3, chamber << " at span " << span << ": network " << area << " mm^2, OCCT " << cavities[k].second);
    worst = std::max(worst, rel);
    ++compared;
  }
  BOOST_TEST(compared >= min_compared, compared << " stations compared");
  BOOST_TEST_MESSAGE("station areas vs OCCT sections: " << compared << " compared, worst relative " << worst);
}

}  // namespace cg::test
