#include "features/film/film_rows.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cg::features {
namespace {

constexpr int kRowSegments = 64;

// Cumulative polyline length at the even nodes of `pts`, extrapolated (Richardson, polyline error h^2).
std::vector<double> cumulative_length(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<double> out{0};
  double fine = 0, coarse = 0;
  for (std::size_t i = 2; i < pts.size(); i += 2) {
    fine += (pts[i - 1] - pts[i - 2]).norm() + (pts[i] - pts[i - 1]).norm();
    coarse += (pts[i] - pts[i - 2]).norm();
    out.push_back(fine + (fine - coarse) / 3);
  }
  return out;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - x.begin()), 1, x.size() - 1);
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

// Unit surface directions at a blade point: streamwise (LE -> TE) and spanwise (towards the tip),
// orthonormal, tangent to the surface.
void surface_directions(const blade::BladeFrame& f, double chord, Eigen::Vector3d& stream, Eigen::Vector3d& span) {
  const Eigen::Vector3d& n = f.normal;
  stream = chord >= 0 ? f.chord_tangent : Eigen::Vector3d(-f.chord_tangent);
  stream = (stream - stream.dot(n) * n).normalized();
  span = f.span_tangent - f.span_tangent.dot(n) * n;
  span = (span - span.dot(stream) * stream).normalized();
}

// A hole leaving along f = cos(a) p + sin(a) n (p unit, tangent): axis d = -f, laidback side sin(a) p - cos(a) n.
HoleFrame hole_frame(const Eigen::Vector3d& exit, const Eigen::Vector3d& n, const Eigen::Vector3d& p, double angle_deg) {
  const double a = angle_deg * kPi / 180;
  HoleFrame hf;
  hf.exit = exit;
  hf.axis = -(std::cos(a) * p + std::sin(a) * n).normalized();
  hf.forward = (std::sin(a) * p - std::cos(a) * n).normalized();
  return hf;
}

// The row curve from span_start to span_end at a row position: arc-length table -> span, chord.
struct RowCurve {
  std::vector<double> spans, arcs;
  double length() const { return arcs.back(); }
};

RowCurve row_curve(const blade::BladeCoordinates& coords, RowPositioner& pos, const RowPosition& at, double s0, double s1) {
  std::vector<Eigen::Vector3d> pts;
  RowCurve rc;
  for (int j = 0; j <= kRowSegments; ++j) {
    const double s = s0 + (s1 - s0) * j / kRowSegments;
    pts.push_back(coords.frame(s, pos.chord(at, s)).point);
    if (j % 2 == 0) rc.spans.push_back(s);
  }
  rc.arcs = cumulative_length(pts);
  return rc;
}

std::string hole_name(const std::string& row, int k) {
  char b[32];
  std::snprintf(b, sizeof b, "_hole_%03d", k);
  return row + b;
}

// Arc-length positions of the holes along a row of length `len`.
std::vector<double> hole_positions(double len, double pitch, int count, double stagger) {
  std::vector<double> x;
  const int n = count > 0 ? count : 1 + static_cast<int>(std::floor(len / pitch + 1e-9));
  const double x0 = count > 0 ? 0.5 * pitch : 0.5 * (len - (n - 1) * pitch);
  for (int k = 0; k < n; ++k) {
    const double v = x0 + k * pitch + stagger * pitch;
    if (v <= len * (1 + 1e-12)) x.push_back(std::min(v, len));
  }
  return x;
}

void check_span_range(double s0, double s1, const std::string& field) {
  if (!(s0 >= 0 && s0 < 1)) throw FilmInputError(field + ".span_start", "span_start " + format_number(s0) + " is outside the blade's span range [0, 1)");
  if (!(s1 > s0 && s1 <= 1)) {
    const ValueRangeText t = format_value_range(s1, s0, 1);
    throw FilmInputError(field + ".span_end", "span_end " + t.value + " must lie in (span_start, 1] = (" + t.lo + ", 1]");
  }
}

}  // namespace

std::pair<double, double> RowPositioner::side_lengths(double span) {
  auto it = cache_.find(span);
  if (it == cache_.end()) {
    const blade::SpanSection& sec = coords_->section(span);
    it = cache_.emplace(span, std::make_pair(sec.suction_length(), sec.pressure_length())).first;
  }
  return it->second;
}

double RowPositioner::chord(const RowPosition& position, double span) {
  if (position.kind == RowPosition::Kind::Chord) return position.value;
  const auto [suction, pressure] = side_lengths(span);
  const double arc = position.value, side = arc >= 0 ? suction : pressure;
  require(std::abs(arc) <= side, "arc length " + format_number(arc) + " mm lies beyond the TE (the " +
                                     (arc >= 0 ? "suction" : "pressure") + " side is " + format_number(side) + " mm long at span " +
                                     format_number(span) + ")");
  return arc / side;
}

std::vector<HoleSpec> place_row(const blade::BladeCoordinates& coords, RowPositioner& positioner,
                                const FilmRowDefinition& row, int row_number, const std::string& field) {
  check_span_range(row.span_start, row.span_end, field);
  const double D = row.shape.diameter;
  if ((row.count > 0) == (row.pitch_d > 0)) throw FilmInputError(field, "give exactly one of count and pitch_d");
  if (row.pitch_d > 0 && row.pitch_d < 1)
    throw FilmInputError(field + ".pitch_d", "pitch " + format_value_limit(row.pitch_d, 1, Allowed::above).value + " D is below the diameter: holes would overlap");
  const RowPosition& at = row.position;
  if (at.kind == RowPosition::Kind::Chord && !(std::abs(at.value) < 1))
    throw FilmInputError(field + ".chord", "chord " + format_value_range(at.value, -1, 1).value + " must lie in (-1, 1)");
  RowCurve rc;
  try {
    rc = row_curve(coords, positioner, at, row.span_start, row.span_end);
  } catch (const InvalidGeometry& e) {
    throw FilmInputError(field + ".arc_length", e.what());
  }
  const double pitch = row.count > 0 ? rc.length() / row.count : row.pitch_d * D;
  if (pitch < D) {
    const ValueLimitText t = format_value_limit(pitch, D, Allowed::above);
    throw FilmInputError(field + ".count", std::to_string(row.count) + " holes over the row's " + format_number(rc.length()) + " mm give a pitch of " +
                                               t.value + " mm, below the diameter " + t.limit + " mm");
  }
  const std::string name = "film_row_" + std::to_string(row_number);
  std::vector<HoleSpec> holes;
  const std::vector<double> xs = hole_positions(rc.length(), pitch, row.count, row.stagger);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    HoleSpec h;
    h.name = hole_name(name, static_cast<int>(k) + 1);
    h.row = name;
    h.field = field;
    h.shape = row.shape;
    h.pitch = pitch;
    h.spacing_field = row.count > 0 ? ".count" : ".pitch_d";
    h.position_field = at.kind == RowPosition::Kind::Chord ? ".chord" : ".arc_length";
    h.required_chamber = row.chamber;
    h.span = interpolate(rc.arcs, rc.spans, xs[k]);
    h.chord = positioner.chord(at, h.span);
    const blade::BladeFrame f = coords.frame(h.span, h.chord);
    Eigen::Vector3d stream, span;
    surface_directions(f, h.chord, stream, span);
    const double b = row.compound_deg * kPi / 180;
    h.frame = hole_frame(f.point, f.normal, std::cos(b) * stream + std::sin(b) * span, row.inclination_deg);
    h.row_direction = span;
    holes.push_back(std::move(h));
  }
  return holes;
}

std::vector<HoleSpec> place_showerhead(const blade::BladeCoordinates& coords, RowPositioner& positioner,
                                       const ShowerheadDefinition& sh, const std::string& field) {
  check_span_range(sh.span_start, sh.span_end, field);
  if (sh.pitch_d < 1) throw FilmInputError(field + ".pitch_d", "pitch " + format_value_limit(sh.pitch_d, 1, Allowed::above).value + " D is below the diameter");
  if (sh.row_spacing_d < 1)
    throw FilmInputError(field + ".row_spacing_d", "row spacing " + format_value_limit(sh.row_spacing_d, 1, Allowed::above).value + " D is below the diameter: rows would overlap");
  std::vector<HoleSpec> holes;
  const double D = sh.diameter;
  for (int k = 1; k <= sh.rows; ++k) {
    FilmRowDefinition row;
    row.shape.kind = HoleKind::Cylindrical;
    row.shape.diameter = D;
    row.position = {RowPosition::Kind::ArcLength, sh.stagnation_arc + (k - 0.5 * (sh.rows + 1)) * sh.row_spacing_d * D};
    row.span_start = sh.span_start;
    row.span_end = sh.span_end;
    row.pitch_d = sh.pitch_d;
    row.stagger = (k % 2 == 0) ? 0.5 : 0.0;
    row.chamber = sh.chamber;
    std::vector<HoleSpec> rh = place_row(coords, positioner, row, k, field);
    const std::string name = "showerhead_" + std::to_string(k);
    for (std::size_t i = 0; i < rh.size(); ++i) {
      HoleSpec& h = rh[i];
      h.name = hole_name(name, static_cast<int>(i) + 1);
      h.row = name;
      h.position_field = ".stagnation_arc_length";
      const blade::BladeFrame f = coords.frame(h.span, h.chord);
      Eigen::Vector3d stream, span;
      surface_directions(f, h.chord, stream, span);
      h.frame = hole_frame(f.point, f.normal, sh.toward_tip ? span : Eigen::Vector3d(-span), sh.radial_angle_deg);
      holes.push_back(std::move(h));
    }
  }
  return holes;
}

std::vector<HoleSpec> place_film_holes(const blade::BladeModel& model, const FilmCoolingDefinition& def) {
  const blade::BladeCoordinates coords(model);
  RowPositioner positioner(coords);
  std::vector<HoleSpec> holes;
  if (def.showerhead) {
    std::vector<HoleSpec> sh = place_showerhead(coords, positioner, *def.showerhead, "showerhead");
    holes.insert(holes.end(), sh.begin(), sh.end());
  }
  for (std::size_t i = 0; i < def.rows.size(); ++i) {
    std::vector<HoleSpec> rh = place_row(coords, positioner, def.rows[i], static_cast<int>(i) + 1,
                                         "film_rows[" + std::to_string(i) + "]");
    holes.insert(holes.end(), rh.begin(), rh.end());
  }
  return holes;
}

}  // namespace cg::features
