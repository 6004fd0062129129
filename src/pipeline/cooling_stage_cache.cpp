#include "src/pipeline/cooling_stage_cache.hpp"

#include <BRep_Builder.hxx>
#include <BinTools.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "export/report.hpp"
#include "export/version.hpp"
#include "features/passages/core_passages.hpp"
#include "src/config/cooling_film_config.hpp"
#include "src/core/error.hpp"
#include "src/pipeline/report.hpp"
#include "src/pipeline/sha256.hpp"

namespace cg::pipeline {
namespace {

using json = nlohmann::ordered_json;  // an entry keeps the order of what it holds (the report's stage times)
using Vec3 = Eigen::Vector3d;

// Bump when the entry's layout changes.
constexpr const char* kFormat = "coolinggen stage cache 3";

// The types an entry stores field by field (or restores in part, see the header); the passage report
// and the blade's check are stored as report.json has them (PassageReport::to_json / from_json,
// io::solid_json / checks_json / solid_check_of). A new field changes the size:
// place it in the entry (encode and decode below) or in the header's list of what is not restored, then
// update the size. Sizes on x86-64 Linux with libstdc++ (the platform the project builds
// and tests on; elsewhere the guard is skipped).
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(features::ChamberInfo) == 88 && sizeof(blade::InnerWallSection) == 64 && sizeof(blade::InnerWall) == 160,
              "ChamberInfo or the inner wall changed: update its codec");
static_assert(sizeof(features::FeatureTool) == 144 && sizeof(features::WallFeatureBuild) == 200 &&
                  sizeof(features::PassagesResult) == 1024 && sizeof(features::CoreBuild) == 664,
              "a cooling stage result type changed: update its codec");
#endif

// Doubles as JSON numbers (shortest round-trip form: exact), non-finite ones as strings.
json num(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
}
double unnum(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf" || s == "-inf") return s[0] == '-' ? -HUGE_VAL : HUGE_VAL;
  throw Error("stage cache: not a number: " + s);
}
json vec(const Vec3& p) { return json::array({num(p.x()), num(p.y()), num(p.z())}); }
Vec3 unvec(const json& j) { return {unnum(j.at(0)), unnum(j.at(1)), unnum(j.at(2))}; }
json nums(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}
std::vector<double> unnums(const json& j) {
  std::vector<double> v;
  for (const json& x : j) v.push_back(unnum(x));
  return v;
}

// ---- shapes and face names

// The faces' names as [index in the shape's face map, orientation, name].
json face_names(const brep::NamedShape& s) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(s.shape, TopAbs_FACE, faces);
  json a = json::array();
  for (const brep::NamedFace& f : s.faces) {
    const int i = faces.FindIndex(f.face);
    if (i == 0) throw Error("stage cache: a named face is not a face of its shape (" + f.name + ")");
    a.push_back(json::array({i, static_cast<int>(f.face.Orientation()), f.name}));
  }
  return a;
}

brep::NamedShape named_shape(const TopoDS_Shape& shape, const json& names) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  brep::NamedShape s{shape, {}};
  for (const json& n : names) {
    const int i = n.at(0).get<int>();
    if (i < 1 || i > faces.Extent()) throw Error("stage cache: face index out of range");
    TopoDS_Face f = TopoDS::Face(faces(i));
    f.Orientation(static_cast<TopAbs_Orientation>(n.at(1).get<int>()));
    s.faces.push_back({f, n.at(2).get<std::string>()});
  }
  return s;
}

std::string shapes_bytes(const std::vector<const TopoDS_Shape*>& shapes) {
  TopoDS_Compound c;
  BRep_Builder b;
  b.MakeCompound(c);
  for (const TopoDS_Shape* s : shapes) b.Add(c, *s);
  std::ostringstream out;
  BinTools::Write(c, out, /*theWithTriangles=*/true, /*theWithNormals=*/true, BinTools_FormatVersion_CURRENT);
  if (!out) throw Error("stage cache: BinTools could not write the shapes");
  return out.str();
}

std::vector<TopoDS_Shape> shapes_of(const std::string& bytes) {
  std::istringstream in(bytes);
  TopoDS_Shape c;
  BinTools::Read(c, in);
  if (c.IsNull() || c.ShapeType() != TopAbs_COMPOUND) throw Error("stage cache: the shapes are not a compound");
  std::vector<TopoDS_Shape> out;
  for (TopoDS_Iterator it(c); it.More(); it.Next()) out.push_back(it.Value());
  return out;
}

// ---- checks and the passage report

// ---- the core's parts the film stage reads

json surface_json(const Surface3& s) {
  const auto& h = s.homogeneous_poles();
  return {{"degree", {s.degree_u(), s.degree_v()}},
          {"knots_u", nums(s.knots_u())},
          {"knots_v", nums(s.knots_v())},
          {"poles", {s.num_poles_u(), s.num_poles_v()}},
          {"homogeneous", nums(std::vector<double>(h.data(), h.data() + h.size()))},
          {"periodic", {s.is_periodic_u(), s.is_periodic_v()}}};
}

Surface3 surface_of(const json& j) {
  const int nu = j.at("poles").at(0).get<int>(), nv = j.at("poles").at(1).get<int>();
  const std::vector<double> h = unnums(j.at("homogeneous"));
  if (h.size() != 4u * static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv)) throw Error("stage cache: surface pole count");
  Surface3::HPoles poles = Eigen::Map<const Surface3::HPoles>(h.data(), 4, static_cast<Eigen::Index>(nu) * nv);
  return Surface3::from_homogeneous(j.at("degree").at(0).get<int>(), j.at("degree").at(1).get<int>(), unnums(j.at("knots_u")),
                                    unnums(j.at("knots_v")), nu, nv, poles, j.at("periodic").at(0).get<bool>(),
                                    j.at("periodic").at(1).get<bool>());
}

// Bit for bit: the film stage must see the surface the passages were built on.
bool same_surface(const Surface3& a, const Surface3& b) {
  if (a.degree_u() != b.degree_u() || a.degree_v() != b.degree_v() || a.knots_u() != b.knots_u() || a.knots_v() != b.knots_v() ||
      a.num_poles_u() != b.num_poles_u() || a.num_poles_v() != b.num_poles_v() || a.is_rational() != b.is_rational() ||
      a.is_periodic_u() != b.is_periodic_u() || a.is_periodic_v() != b.is_periodic_v() ||
      a.homogeneous_poles() != b.homogeneous_poles())
    return false;
  for (int i = 0; i < a.num_poles_u(); ++i)
    for (int k = 0; k < a.num_poles_v(); ++k)
      if (a.pole(i, k) != b.pole(i, k)) return false;
  return true;
}

json inner_wall_json(const blade::InnerWall& w) {
  json sections = json::array();
  for (const auto& s : w.sections)
    sections.push_back({num(s.span), num(s.suction_chord), num(s.pressure_chord), num(s.pressure_span), s.trimmed, vec(s.crease)});
  return {{"surface", surface_json(w.surface)},
          {"sections", sections},
          {"max_fit_error", num(w.max_fit_error)},
          {"checked_points", w.checked_points},
          {"min_suction_chord", num(w.min_suction_chord)},
          {"max_pressure_chord", num(w.max_pressure_chord)}};
}

blade::InnerWall inner_wall_of(const json& j) {
  blade::InnerWall w;
  w.surface = surface_of(j.at("surface"));
  for (const json& s : j.at("sections"))
    w.sections.push_back({unnum(s.at(0)), unnum(s.at(1)), unnum(s.at(2)), unnum(s.at(3)), s.at(4).get<bool>(), unvec(s.at(5))});
  w.max_fit_error = unnum(j.at("max_fit_error"));
  w.checked_points = j.at("checked_points").get<int>();
  w.min_suction_chord = unnum(j.at("min_suction_chord"));
  w.max_pressure_chord = unnum(j.at("max_pressure_chord"));
  return w;
}

json core_json(const features::CoreBuild& c) {
  json chambers = json::array();
  for (const auto& k : c.chambers)
    chambers.push_back({k.number, num(k.suction_from), num(k.suction_to), num(k.pressure_from), num(k.pressure_to), vec(k.reference),
                        k.system, num(k.volume), k.fed});
  json seconds = json::array();
  for (const auto& [stage, s] : c.seconds) seconds.push_back({stage, num(s)});
  // An end wall is EndWall(model, end, shift) (build_core_walls); its shift is stored.
  const auto end = [](const std::optional<features::EndWall>& w) { return w ? num(w->shift()) : json(nullptr); };
  return {{"inner_wall", inner_wall_json(c.inner_wall)},
          {"chambers", chambers},
          {"hub_floor_shift", end(c.hub_floor)},
          {"tip_cap_shift", end(c.tip_cap)},
          {"core_volume", num(c.core_volume)},
          {"rib_volumes", nums(c.rib_volumes)},
          {"fillet_volumes", nums(c.fillet_volumes)},
          {"inlet_volumes", nums(c.inlet_volumes)},
          {"seconds", seconds}};
}

features::CoreBuild core_of(const json& j, const blade::BladeModel& model) {
  features::CoreBuild c;
  c.inner_wall = inner_wall_of(j.at("inner_wall"));
  for (const json& k : j.at("chambers"))
    c.chambers.push_back({k.at(0).get<int>(), unnum(k.at(1)), unnum(k.at(2)), unnum(k.at(3)), unnum(k.at(4)), unvec(k.at(5)),
                          k.at(6).get<int>(), unnum(k.at(7)), k.at(8).get<bool>()});
  if (!j.at("hub_floor_shift").is_null()) c.hub_floor.emplace(model, features::SpanEnd::Hub, unnum(j.at("hub_floor_shift")));
  if (!j.at("tip_cap_shift").is_null()) c.tip_cap.emplace(model, features::SpanEnd::Tip, unnum(j.at("tip_cap_shift")));
  c.core_volume = unnum(j.at("core_volume"));
  c.rib_volumes = unnums(j.at("rib_volumes"));
  c.fillet_volumes = unnums(j.at("fillet_volumes"));
  c.inlet_volumes = unnums(j.at("inlet_volumes"));
  for (const json& s : j.at("seconds")) c.seconds.emplace_back(s.at(0).get<std::string>(), unnum(s.at(1)));
  return c;
}

// The wall-feature tool groups, in the order of the entry's shapes after the blade.
struct ToolGroups {
  std::vector<features::FeatureTool>* lists[3];
  static constexpr const char* names[3] = {"turbulators", "pin_fins", "te_slots"};
};
ToolGroups groups(features::WallFeatureBuild& w) {
  return {{&w.turbulators.tools, &w.trailing_edge.pin_tools, &w.trailing_edge.slot_tools}};
}

json tool_json(const features::FeatureTool& t) {
  json axis = nullptr;
  if (t.symmetry_axis) {
    const gp_Pnt& p = t.symmetry_axis->Location();
    const gp_Dir& d = t.symmetry_axis->Direction();
    axis = nums({p.X(), p.Y(), p.Z(), d.X(), d.Y(), d.Z()});
  }
  return {{"feature", t.feature}, {"faces", face_names(t.shape)}, {"expected_volume", num(t.expected_volume)}, {"symmetry_axis", axis}};
}

features::FeatureTool tool_of(const json& j, const TopoDS_Shape& shape) {
  features::FeatureTool t;
  t.feature = j.at("feature").get<std::string>();
  t.shape = named_shape(shape, j.at("faces"));
  t.expected_volume = unnum(j.at("expected_volume"));
  if (!j.at("symmetry_axis").is_null()) {
    const std::vector<double> a = unnums(j.at("symmetry_axis"));
    t.symmetry_axis = gp_Ax1(gp_Pnt(a.at(0), a.at(1), a.at(2)), gp_Dir(a.at(3), a.at(4), a.at(5)));
  }
  return t;
}

// SHA-256 of the file that holds this code (the coolinggen binary, or the library a host loaded), once.
const std::string& binary_fingerprint() {
  static const std::string fingerprint = [] {
    // The shared object this function is in (a host program's library), else the executable.
    Dl_info info{};
    std::string file = "/proc/self/exe";
    if (dladdr(reinterpret_cast<const void*>(&binary_fingerprint), &info) != 0 && info.dli_fname && *info.dli_fname &&
        std::ifstream(info.dli_fname).good())
      file = info.dli_fname;
    std::ifstream in(file, std::ios::binary);
    // Unreadable: a fingerprint of this process alone (its entries are never read by another one).
    if (!in) return "unread binary, process " + std::to_string(::getpid()) + " " + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    Sha256 h;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) h.update(buffer, static_cast<std::size_t>(in.gcount()));
    return h.hex_digest();
  }();
  return fingerprint;
}

}  // namespace

const std::vector<std::string> kNotCoolingInputs = [] {
  std::vector<std::string> v{"$schema", "name", "description", "output", "mesh", "grid", "coolant"};
  for (const char* k : config::kFilmCoolingKeys) v.push_back(std::string("cooling.") + k);
  return v;
}();

std::string cooling_stage_key(const config::Config& c, features::Verification verification) {
  json document = c.source;
  for (const std::string& path : kNotCoolingInputs) {
    const std::size_t dot = path.find('.');
    if (dot == std::string::npos) document.erase(path);
    else if (document.contains(path.substr(0, dot)) && document[path.substr(0, dot)].is_object())
      document[path.substr(0, dot)].erase(path.substr(dot + 1));
  }
  Sha256 h;
  for (const std::string& part : {std::string(kFormat), std::string(io::tool_version()), binary_fingerprint(), std::string(kCoolingStage),
                                  std::string(verification == features::Verification::EachStep ? "verify_each_step" : "verify_once")}) {
    h.update(std::to_string(part.size()) + ":");
    h.update(part);
  }
  hash_inputs(h, document, c);
  return h.hex_digest();
}

StageCacheEntry encode_cooling_stage(const features::PassagesResult& r) {
  StageCacheEntry e;
  std::vector<const TopoDS_Shape*> shapes{&r.blade.shape};
  json tools = json::object();
  features::WallFeatureBuild walls = r.wall_features;
  const ToolGroups g = groups(walls);
  for (std::size_t i = 0; i < 3; ++i) {
    tools[ToolGroups::names[i]] = json::array();
    for (const features::FeatureTool& t : *g.lists[i]) {
      tools[ToolGroups::names[i]].push_back(tool_json(t));
      shapes.push_back(&t.shape.shape);
    }
  }
  e.shapes = shapes_bytes(shapes);
  e.data = {{"format", kFormat},
            {"version", io::tool_version()},
            {"blade_faces", face_names(r.blade)},
            {"tools", tools},
            {"report", r.report.to_json()},
            {"check", r.checked ? json{{"solid", io::solid_json(r.check, {})}, {"checks", io::checks_json(r.check)}} : json(nullptr)},
            {"checked", r.checked},
            {"core", r.core ? core_json(*r.core) : json(nullptr)}};
  if (r.core && !same_surface(surface_of(e.data["core"]["inner_wall"]["surface"]), r.core->inner_wall.surface))
    throw Error("stage cache: the inner wall surface does not come back bit for bit");
  return e;
}

features::PassagesResult decode_cooling_stage(const StageCacheEntry& e, const blade::BladeModel& model) {
  const json& d = e.data;
  if (d.value("format", "") != kFormat) throw Error("stage cache: an entry of another format");
  const std::vector<TopoDS_Shape> shapes = shapes_of(e.shapes);
  features::PassagesResult r;
  r.blade = named_shape(shapes.at(0), d.at("blade_faces"));
  std::size_t next = 1;
  const ToolGroups g = groups(r.wall_features);
  for (std::size_t i = 0; i < 3; ++i)
    for (const json& t : d.at("tools").at(ToolGroups::names[i])) g.lists[i]->push_back(tool_of(t, shapes.at(next++)));
  if (next != shapes.size()) throw Error("stage cache: the entry has more shapes than tools");
  r.report = features::PassageReport::from_json(d.at("report"));
  if (!d.at("check").is_null()) r.check = io::solid_check_of(d.at("check").at("solid"), d.at("check").at("checks"));
  r.checked = d.at("checked").get<bool>();
  if (!d.at("core").is_null()) r.core = std::make_shared<const features::CoreBuild>(core_of(d.at("core"), model));
  return r;
}

}  // namespace cg::pipeline
