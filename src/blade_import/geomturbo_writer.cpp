#include "src/blade_import/geomturbo_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>

#include "src/core/format.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg::blade_import {
namespace {

void zr_curve(std::ostream& o, const char* name, const std::vector<Eigen::Vector2d>& pts) {
  o << "NI_BEGIN basic_curve\nNAME " << name << "\nDISCRETISATION 10\nDATA_REDUCTION 0\nNI_BEGIN zrcurve\nZR\n"
    << pts.size() << "\n";
  for (const auto& p : pts) o << format_round_trip(p.x()) << " " << format_round_trip(p.y()) << "\n";
  o << "NI_END zrcurve\nNI_END basic_curve\n";
}

void channel_curve(std::ostream& o, const char* which, const char* curve) {
  o << "NI_BEGIN channel_curve " << which << "\nNAME " << which << "\nVERTEX CURVE_P " << curve << " 0\nVERTEX CURVE_P "
    << curve << " 1\nNI_END channel_curve " << which << "\n";
}

std::vector<Eigen::Vector2d> contour(const BSplineCurve<2>& c, int n) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i) out.push_back(c.point(c.first_param() + (c.last_param() - c.first_param()) * i / (n - 1)));
  return out;
}

// One side LE -> TE at span v; suction: increasing u, pressure: decreasing u.
std::vector<Eigen::Vector3d> side(const blade::BladeModel& m, double v, bool suction, int n) {
  double d = m.u_te - m.u_le;
  d -= std::floor(d);
  const double span_u = suction ? d : -(1 - d);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) {
    const double f = 0.5 * (1 - std::cos(kPi * i / (n - 1)));
    double u = m.u_le + f * span_u;
    u -= std::floor(u);
    out.push_back(m.surface.point(u, v));
  }
  return out;
}

void write_side(std::ostream& o, const blade::BladeModel& m, bool suction, const GeomTurboWriteOptions& opt) {
  o << (suction ? "suction" : "pressure") << "\nSECTIONAL\n" << opt.sections << "\n";
  const double ob = m.options.overbuild;
  for (int k = 0; k < opt.sections; ++k) {
    const double v = -ob + (1 + 2 * ob) * k / (opt.sections - 1);
    o << "# section " << k + 1 << "\n" << (m.trim.straight ? "XYZ" : "ZRTH") << "\n" << opt.points_per_side << "\n";
    for (const Eigen::Vector3d& p : side(m, v, suction, opt.points_per_side)) {
      if (m.trim.straight) o << format_round_trip(p.z() - m.trim.hub_z) << " " << format_round_trip(p.y()) << " " << format_round_trip(p.x()) << "\n";
      else o << format_round_trip(p.x()) << " " << format_round_trip(std::hypot(p.y(), p.z())) << " " << format_round_trip(std::atan2(p.z(), p.y())) << "\n";
    }
  }
}

}  // namespace

void write_geomturbo(std::ostream& o, const blade::BladeModel& m, const GeomTurboWriteOptions& opt) {
  require(opt.sections >= 2 && opt.points_per_side >= 3, "geomTurbo: at least 2 sections of 3 points per side");
  const int blades = opt.number_of_blades > 0 ? opt.number_of_blades : m.imported ? m.imported->number_of_blades : 0;
  o << "GEOMETRY TURBO\nVERSION 5.5\nTOLERANCE 1e-06\nUNITS Millimeters\nUNITS-FACTOR 1\n";
  if (m.trim.straight) o << "cascade yes\n";
  o << "NI_BEGIN CHANNEL\n";
  if (m.trim.straight) {
    // The cascade's channel: hub r = 0 and shroud r = span, a chord ahead of and behind the blade.
    double x0 = 1e300, x1 = -1e300;
    for (bool s : {true, false})
      for (const auto& p : side(m, 0.5, s, 64)) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    const double c = x1 - x0, span = m.trim.casing_z - m.trim.hub_z;
    zr_curve(o, "hub_curve", {{x0 - c, 0.0}, {x1 + c, 0.0}});
    zr_curve(o, "shroud_curve", {{x0 - c, span}, {x1 + c, span}});
  } else {
    zr_curve(o, "hub_curve", contour(m.trim.hub, 201));
    zr_curve(o, "shroud_curve", contour(m.trim.casing, 201));
  }
  channel_curve(o, "hub", "hub_curve");
  channel_curve(o, "shroud", "shroud_curve");
  o << "NI_END CHANNEL\nNI_BEGIN nirow\nNAME row_1\nTYPE normal\n";
  if (blades > 0) o << "PERIODICITY " << blades << "\n";
  o << "NI_BEGIN NIBlade\nNAME Main_Blade\nNI_BEGIN nibladegeometry\nTYPE GEOMTURBO\nGEOMETRY_MODIFIED 0\n"
       "GEOMETRY TURBO VERSION 5\nunits 1\n";
  if (blades > 0) o << "number_of_blades " << blades << "\n";
  write_side(o, m, true, opt);
  write_side(o, m, false, opt);
  o << "NI_END nibladegeometry\nNI_END NIBlade\nNI_END nirow\nNI_END GEOMTURBO\n";
}

void write_geomturbo_file(const std::string& path, const blade::BladeModel& model, const GeomTurboWriteOptions& options) {
  std::ofstream out(path);
  if (!out) throw Error("geomTurbo: cannot write " + path);
  write_geomturbo(out, model, options);
  out.close();
  if (!out) throw Error("geomTurbo: writing " + path + " failed");
}

}  // namespace cg::blade_import
