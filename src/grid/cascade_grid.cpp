// The cascade layout of section_grid.hpp: periodic O-grid with inlet and outlet blocks.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>

#include "src/algo/ray_curve.hpp"
#include "src/core/format.hpp"
#include "src/core/error.hpp"
#include "src/grid/builders.hpp"
#include "src/grid/distribution.hpp"
#include "src/grid/grid_repair.hpp"
#include "src/grid/mid_line.hpp"
#include "src/grid/wall_nodes.hpp"

namespace cg::grid::detail {

namespace {

// Interface positions: upstream of the LE by this many axial chords (and at least this many wall-layer
// thicknesses), downstream of the TE by this many axial chords (the near wake stays in the O-grid, so
// the TE's grid lines can follow a steep exit angle instead of fanning out sideways).
constexpr double kInletGap = 0.3, kInterfaceGapLayers = 2.5, kOutletGap = 0.4;
// Share of the uniform correspondence mixed into the normal-ray one (see build_cascade_grid).
constexpr double kUniformShare = 0.1;

std::string mm(double x) { return format_number(x) + " mm"; }

// Cubic Hermite curve from R (tangent T0) to O (tangent T1), sampled by arc length: the nodes at the
// given distances along it (the polyline of 128 samples is inverted linearly).
std::vector<Eigen::Vector2d> hermite_nodes(const Eigen::Vector2d& R, const Eigen::Vector2d& T0, const Eigen::Vector2d& O,
                                           const Eigen::Vector2d& T1, double first, int cells) {
  auto P = [&](double t) {
    const double t2 = t * t, t3 = t2 * t;
    return Eigen::Vector2d((2 * t3 - 3 * t2 + 1) * R + (t3 - 2 * t2 + t) * T0 + (-2 * t3 + 3 * t2) * O + (t3 - t2) * T1);
  };
  const int n = 128;
  std::vector<double> len(n + 1, 0.0);
  Eigen::Vector2d prev = R;
  for (int k = 1; k <= n; ++k) {
    const Eigen::Vector2d p = P(static_cast<double>(k) / n);
    len[static_cast<std::size_t>(k)] = len[static_cast<std::size_t>(k) - 1] + (p - prev).norm();
    prev = p;
  }
  const std::vector<double> s = geometric_fill(std::min(first, len.back() / cells), cells, len.back());
  std::vector<Eigen::Vector2d> out;
  std::size_t seg = 1;
  for (int c = 0; c <= cells; ++c) {
    const double target = s[static_cast<std::size_t>(c)];
    while (seg < static_cast<std::size_t>(n) && len[seg] < target) ++seg;
    const double a = len[seg - 1], b = len[seg];
    const double t = (static_cast<double>(seg - 1) + (b > a ? (target - a) / (b - a) : 0.0)) / n;
    out.push_back(c == 0 ? R : c == cells ? O : P(t));
  }
  return out;
}

}  // namespace

std::pair<double, double> axial_range(const blade::SectionProfile& section) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int k = 0; k < 2000; ++k) {
    const double a = section.curve.point(section.curve.first_param() + section.curve.period() * k / 2000).x();
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  return {lo, hi};
}

namespace {

// The passage's axial stations: the O-grid's interfaces and the inlet and outlet planes.
struct Stations {
  double a_in = 0, a_out = 0, a_inlet = 0, a_outlet = 0;
};

// The periodic lines: the mid-line moved by +-pitch / 2 along b (`which` = +-1); `up` (+-1) is the one
// facing the suction side.
struct PeriodicLines {
  const MidLine& mid;
  double pitch = 0, up = 1;
  double y(double a, double which) const { return mid.y(a) + which * 0.5 * pitch; }
};

// The periodic lines must clear the section with room for the wall layers on both sides of the
// passage: pitch/2 >= (largest distance of the section from its mid-line along b) + 2 thickness; the
// interfaces and the inlet and outlet planes.
Stations passage_stations(const blade::SectionProfile& section, const MidLine& mid, const SectionGridOptions& o, double a_min,
                          double a_max) {
  const CascadeOptions& cas = *o.cascade;
  const double pitch = cas.pitch;
  const double c_ax = a_max - a_min;
  std::vector<Eigen::Vector2d> wall_sample;
  for (int k = 0; k < 2000; ++k)
    wall_sample.push_back(section.curve.point(section.curve.first_param() + section.curve.period() * k / 2000));
  double reach = 0, reach_a = 0;
  for (const Eigen::Vector2d& p : wall_sample) {
    const double off = std::abs(p.y() - mid.y(p.x()));
    if (off > reach) {
      reach = off;
      reach_a = p.x();
    }
  }
  const double need = 2 * (reach + 2 * o.thickness);
  if (pitch < need)
    throw InvalidGeometry("cascade.pitch: " + mm(pitch) + " is too small: the section reaches " + mm(reach) +
                          " from its mid-line (at a = " + mm(reach_a) + ") and the wall layers need " +
                          mm(2 * o.thickness) + " more on each side; need pitch >= " + mm(need));
  const double gap_in = std::max(kInletGap * c_ax, kInterfaceGapLayers * o.thickness);
  const double gap_out = std::max(kOutletGap * c_ax, kInterfaceGapLayers * o.thickness);
  Stations st;
  st.a_in = a_min - gap_in, st.a_out = a_max + gap_out;
  st.a_inlet = a_min - cas.inlet_distance, st.a_outlet = a_max + cas.outlet_distance;
  if (!(st.a_inlet < st.a_in - 1e-9 * c_ax))
    throw InvalidGeometry("cascade.inlet_distance: must exceed " + mm(gap_in) +
                          " (the O-grid reaches that far upstream of the section)");
  if (!(st.a_outlet > st.a_out + 1e-9 * c_ax))
    throw InvalidGeometry("cascade.outlet_distance: must exceed " + mm(gap_out) +
                          " (the O-grid reaches that far downstream of the section)");
  return st;
}

// Outer loop, in the wall's rotational order: the inlet interface from the pressure-facing corner to the
// suction-facing one, the suction-facing periodic line (a_in -> a_out), the outlet interface, the
// pressure-facing line (a_out -> a_in). Interfaces uniform; the periodic lines uniform in arc length,
// the same a values on both, so their nodes match by the pitch translation.
std::vector<Eigen::Vector2d> outer_nodes(const PeriodicLines& lines, const Stations& st, int n_in, int n_per, int n_out) {
  const double a_in = st.a_in, a_out = st.a_out, pitch = lines.pitch, up = lines.up;
  const MidLine& mid = lines.mid;
  std::vector<double> a_per(static_cast<std::size_t>(n_per) + 1);
  {
    const int dense = 40 * n_per;
    std::vector<double> a(static_cast<std::size_t>(dense) + 1), len(static_cast<std::size_t>(dense) + 1, 0.0);
    for (int k = 0; k <= dense; ++k) {
      a[static_cast<std::size_t>(k)] = a_in + (a_out - a_in) * k / dense;
      if (k > 0)
        len[static_cast<std::size_t>(k)] = len[static_cast<std::size_t>(k) - 1] +
                                           std::hypot(a[static_cast<std::size_t>(k)] - a[static_cast<std::size_t>(k) - 1],
                                                      mid.y(a[static_cast<std::size_t>(k)]) - mid.y(a[static_cast<std::size_t>(k) - 1]));
    }
    std::size_t seg = 1;
    for (int k = 0; k <= n_per; ++k) {
      const double target = len.back() * k / n_per;
      while (seg < a.size() - 1 && len[seg] < target) ++seg;
      const double f = (target - len[seg - 1]) / (len[seg] - len[seg - 1]);
      a_per[static_cast<std::size_t>(k)] = a[seg - 1] + f * (a[seg] - a[seg - 1]);
    }
    a_per.front() = a_in;
    a_per.back() = a_out;
  }
  std::vector<Eigen::Vector2d> outer;
  for (int k = 0; k < n_in; ++k) outer.emplace_back(a_in, lines.y(a_in, -up) + up * pitch * k / n_in);
  for (int k = 0; k < n_per; ++k) outer.emplace_back(a_per[static_cast<std::size_t>(k)], lines.y(a_per[static_cast<std::size_t>(k)], up));
  for (int k = 0; k < n_out; ++k) outer.emplace_back(a_out, lines.y(a_out, up) - up * pitch * k / n_out);
  for (int k = 0; k < n_per; ++k)
    outer.emplace_back(a_per[static_cast<std::size_t>(n_per - k)], lines.y(a_per[static_cast<std::size_t>(n_per - k)], -up));
  return outer;
}

// The outer loop as a dense closed polyline (100 points per piece), its arc lengths and its curve.
struct OuterLoop {
  std::vector<Eigen::Vector2d> loop;
  std::vector<double> loop_len;
  double L = 0;
  BSplineCurve<2> curve;
};

OuterLoop outer_loop(const PeriodicLines& lines, const Stations& st) {
  const double a_in = st.a_in, a_out = st.a_out, pitch = lines.pitch, up = lines.up;
  std::vector<Eigen::Vector2d> loop;  // dense closed polyline of the outer loop
  {
    auto add_piece = [&](const std::function<Eigen::Vector2d(double)>& f) {
      for (int k = 0; k < 100; ++k) loop.push_back(f(k / 100.0));
    };
    add_piece([&](double t) { return Eigen::Vector2d(a_in, lines.y(a_in, -up) + up * pitch * t); });
    add_piece([&](double t) { const double a = a_in + (a_out - a_in) * t; return Eigen::Vector2d(a, lines.y(a, up)); });
    add_piece([&](double t) { return Eigen::Vector2d(a_out, lines.y(a_out, up) - up * pitch * t); });
    add_piece([&](double t) { const double a = a_out - (a_out - a_in) * t; return Eigen::Vector2d(a, lines.y(a, -up)); });
    loop.push_back(loop.front());
  }
  std::vector<double> loop_len(loop.size(), 0.0);
  for (std::size_t k = 1; k < loop.size(); ++k) loop_len[k] = loop_len[k - 1] + (loop[k] - loop[k - 1]).norm();
  const double L = loop_len.back();
  std::vector<double> knots{0.0};
  for (double x : loop_len) knots.push_back(x);
  knots.push_back(L);
  BSplineCurve<2> curve(1, knots, loop);
  return OuterLoop{std::move(loop), std::move(loop_len), L, std::move(curve)};
}

// Loop arc length of each outer node (they lie on the polyline's pieces).
std::vector<double> outer_node_positions(const OuterLoop& ol, const std::vector<Eigen::Vector2d>& outer, int n_in, int n_per,
                                         int n_out) {
  const std::vector<Eigen::Vector2d>& loop = ol.loop;
  const std::vector<double>& loop_len = ol.loop_len;
  std::vector<double> tau_outer(outer.size());
  const int pieces[4] = {n_in, n_per, n_out, n_per};
  std::size_t k = 0;
  for (int piece = 0; piece < 4; ++piece)
    for (int c = 0; c < pieces[piece]; ++c, ++k) {
      // Nearest polyline vertex within this piece, then the projection onto its neighbouring edges.
      double best = HUGE_VAL, tau = 0;
      for (int v = piece * 100; v < (piece + 1) * 100; ++v) {
        const Eigen::Vector2d e = loop[static_cast<std::size_t>(v) + 1] - loop[static_cast<std::size_t>(v)];
        const double f = std::clamp((outer[k] - loop[static_cast<std::size_t>(v)]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        const double d = (loop[static_cast<std::size_t>(v)] + f * e - outer[k]).squaredNorm();
        if (d < best) {
          best = d;
          tau = loop_len[static_cast<std::size_t>(v)] + f * e.norm();
        }
      }
      tau_outer[k] = tau;
    }
  return tau_outer;
}

// Wall nodes from the outer ones through the wall normals: the normal ray from the last wall layer at
// wall position s first hits the outer loop at loop arc length tau(s) (exact line-polyline
// intersections, src/algo/ray_curve.hpp). tau, made monotone, is the natural correspondence: the wall
// node of outer node k sits at s = tau^-1(tau_k), so every grid line leaves the wall layers about
// towards its outer node, and where the normals fan out (LE, TE) the wall nodes crowd.
// The wall positions s of the outer nodes (ni + 1, the last one round).
std::vector<double> wall_positions(const WallArc& arc, const WallPatches& patches, const SectionGridOptions& o,
                                   const OuterLoop& ol, const std::vector<double>& tau_outer) {
  const int ni = o.cells_around;
  const double P = arc.perimeter(), L = ol.L;
  const int samples = 16 * ni;
  std::vector<double> s_samples(static_cast<std::size_t>(samples) + 1), tau(static_cast<std::size_t>(samples) + 1);
  for (int j = 0; j <= samples; ++j) s_samples[static_cast<std::size_t>(j)] = P * j / samples;
  const std::vector<double> u_samples = arc.params(s_samples);
  for (int j = 0; j <= samples; ++j) {
    const double u = u_samples[static_cast<std::size_t>(j)];
    const Eigen::Vector2d R = patches.point(u, o.thickness), n = patches.outer_normal(u);
    const auto hits = line_curve_intersections(ol.curve, R, n, 0.0);
    tau[static_cast<std::size_t>(j)] = hits.empty() ? (j > 0 ? tau[static_cast<std::size_t>(j) - 1] : 0.0) : hits.front().curve_param;
  }
  // Unwrap and make non-decreasing, then scale to exactly one loop per wall round.
  for (int j = 1; j <= samples; ++j) {
    double d = tau[static_cast<std::size_t>(j)] - tau[static_cast<std::size_t>(j) - 1];
    d -= L * std::round(d / L);
    tau[static_cast<std::size_t>(j)] = tau[static_cast<std::size_t>(j) - 1] + std::max(d, 1e-6 * L / samples);
  }
  // Smooth the correspondence: its slope (outer length per wall length) is the ratio of outer to wall
  // spacing. A Gaussian over about one mean wall cell keeps neighbouring wall cells within a small
  // factor, and a share kUniformShare of the mean slope keeps the wall cells of concave stretches (whose
  // normals converge onto a short piece of the outer loop) at most 1 / kUniformShare times the mean.
  {
    std::vector<double> slope(static_cast<std::size_t>(samples));
    for (int j = 0; j < samples; ++j)
      slope[static_cast<std::size_t>(j)] = (tau[static_cast<std::size_t>(j) + 1] - tau[static_cast<std::size_t>(j)]) / (P / samples);
    const double mean_slope = L / P;
    std::vector<double> smooth = smooth_periodic(slope, 1.0 * samples / ni);
    for (double& x : smooth) x = (1 - kUniformShare) * x + kUniformShare * mean_slope;
    double total = 0;
    for (double x : smooth) total += x * P / samples;
    for (int j = 0; j < samples; ++j)
      tau[static_cast<std::size_t>(j) + 1] = tau[static_cast<std::size_t>(j)] + smooth[static_cast<std::size_t>(j)] * (P / samples) * L / total;
  }
  // Wall position of each outer node: tau^-1, with outer nodes before tau(0) taken one loop later; the
  // O-grid's i = 0 stays at the outer loop's start, so those wall positions come out one perimeter early.
  std::vector<double> s_wall(static_cast<std::size_t>(ni) + 1);
  for (int k = 0; k < ni; ++k) {
    double t = tau_outer[static_cast<std::size_t>(k)];
    bool wrapped = false;
    if (t < tau.front()) {
      t += L;
      wrapped = true;
    }
    const auto it = std::lower_bound(tau.begin(), tau.end(), t);
    const std::size_t j = std::clamp<std::size_t>(static_cast<std::size_t>(it - tau.begin()), 1, tau.size() - 1);
    const double f = (t - tau[j - 1]) / std::max(tau[j] - tau[j - 1], 1e-300);
    const double sw = s_samples[j - 1] + std::clamp(f, 0.0, 1.0) * (s_samples[j] - s_samples[j - 1]);
    s_wall[static_cast<std::size_t>(k)] = wrapped ? sw - P : sw;
  }
  s_wall.back() = s_wall.front() + P;
  return s_wall;
}

// Wall layers on the patches, then Hermite curves to the outer boundary (`outer` closed: ni + 1 nodes).
Block o_grid_block(const WallPatches& patches, const SectionGridOptions& o, int wall_layers,
                   const std::vector<double>& wall_params, const std::vector<Eigen::Vector2d>& outer) {
  const int ni = o.cells_around, nj = o.cells_normal;
  double ratio = 1;
  const std::vector<double> s_layers = geometric_fill(o.first_cell_height, wall_layers, o.thickness, &ratio);
  const double next_cell = (s_layers[static_cast<std::size_t>(wall_layers)] - s_layers[static_cast<std::size_t>(wall_layers) - 1]) * ratio;
  Block og("o_grid", ni, nj);
  for (int i = 0; i < ni; ++i) {
    const double u = wall_params[static_cast<std::size_t>(i)];
    for (int j = 0; j <= wall_layers; ++j) og.at(i, j) = patches.point(u, s_layers[static_cast<std::size_t>(j)]);
    const Eigen::Vector2d R = og.at(i, wall_layers), O = outer[static_cast<std::size_t>(i)];
    const double dist = (O - R).norm();
    const std::vector<Eigen::Vector2d> line =
        hermite_nodes(R, patches.outer_normal(u) * dist, O, O - R, next_cell, nj - wall_layers);
    for (int j = wall_layers; j <= nj; ++j) og.at(i, j) = line[static_cast<std::size_t>(j - wall_layers)];
  }
  for (int j = 0; j <= nj; ++j) og.at(ni, j) = og.at(0, j);
  untangle(og, wall_layers, 50);
  improve_worst_cells(og, wall_layers, 0.3, 50);
  return og;
}

// Inlet and outlet blocks: i streamwise (+a), j across the passage (+b), lines a = const between the
// periodic lines, uniform in both directions (pitchwise as the O-grid's interfaces).
void add_inlet_outlet_blocks(BuiltGrid& out, const PeriodicLines& lines, const Stations& st, const SectionGridOptions& o,
                             int n_in, int n_per, int n_out) {
  const CascadeOptions& cas = *o.cascade;
  const int nj = o.cells_normal;
  const double pitch = lines.pitch, up = lines.up;
  auto h_block = [&](const char* name, double a0, double a1, int ns, int np) {
    Block b(name, ns, np);
    for (int i = 0; i <= ns; ++i) {
      const double a = a0 + (a1 - a0) * i / ns;
      for (int j = 0; j <= np; ++j) b.at(i, j) = {a, lines.y(a, -1) + pitch * j / np};
    }
    return b;
  };
  out.grid.blocks.push_back(h_block("inlet", st.a_inlet, st.a_in, cas.inlet_cells_streamwise, n_in));
  out.grid.blocks.push_back(h_block("outlet", st.a_out, st.a_outlet, cas.outlet_cells_streamwise, n_out));
  // The interface nodes must be bit-identical to the O-grid's: copy them over.
  Block& og_ref = out.grid.blocks[0];
  Block& inlet = out.grid.blocks[1];
  Block& outlet = out.grid.blocks[2];
  for (int k = 0; k <= n_in; ++k) inlet.at(inlet.ni, up > 0 ? k : n_in - k) = og_ref.at(k, nj);
  for (int k = 0; k <= n_out; ++k) outlet.at(0, up > 0 ? n_out - k : k) = og_ref.at(n_in + n_per + k, nj);
}

// The blocks' connections (the O-grid's cut, the periodic pairs, the interfaces) and boundaries.
void connect_cascade(BuiltGrid& out, const SectionGridOptions& o, double pitch, double up, int n_in, int n_per, int n_out) {
  const CascadeOptions& cas = *o.cascade;
  const int ni = o.cells_around, nj = o.cells_normal;
  const Eigen::Vector2d shift(0, pitch);
  auto& C = out.grid.connections;
  C.push_back({"o_cut", 0, {Face::IMin, 0, nj}, 0, {Face::IMax, 0, nj}, false, Eigen::Vector2d::Zero()});
  // Periodic pair of the O-grid: the line at -b (lower) + pitch = the line at +b, node k from a_in.
  const int i_suction = n_in, i_pressure_end = ni;  // suction line i = n_in + k; pressure line i = ni - k
  const FaceRange suction_range{Face::JMax, i_suction, i_suction + n_per};
  const FaceRange pressure_range{Face::JMax, i_pressure_end, i_pressure_end - n_per};
  if (up > 0)
    C.push_back({"o_periodic", 0, pressure_range, 0, suction_range, true, shift});
  else
    C.push_back({"o_periodic", 0, suction_range, 0, pressure_range, true, shift});
  C.push_back({"inlet_interface", 1, {Face::IMax, 0, n_in}, 0,
               up > 0 ? FaceRange{Face::JMax, 0, n_in} : FaceRange{Face::JMax, n_in, 0}, false, Eigen::Vector2d::Zero()});
  C.push_back({"outlet_interface", 2, {Face::IMin, 0, n_out}, 0,
               up > 0 ? FaceRange{Face::JMax, n_in + n_per + n_out, n_in + n_per}
                      : FaceRange{Face::JMax, n_in + n_per, n_in + n_per + n_out},
               false, Eigen::Vector2d::Zero()});
  C.push_back({"inlet_periodic", 1, {Face::JMin, 0, cas.inlet_cells_streamwise}, 1,
               {Face::JMax, 0, cas.inlet_cells_streamwise}, true, shift});
  C.push_back({"outlet_periodic", 2, {Face::JMin, 0, cas.outlet_cells_streamwise}, 2,
               {Face::JMax, 0, cas.outlet_cells_streamwise}, true, shift});
  auto& B = out.grid.boundaries;
  B.push_back({"wall", BoundaryKind::Wall, 0, {Face::JMin, 0, ni}});
  B.push_back({"inlet", BoundaryKind::Inlet, 1, {Face::IMin, 0, n_in}});
  B.push_back({"outlet", BoundaryKind::Outlet, 2, {Face::IMax, 0, n_out}});
}

}  // namespace

BuiltGrid build_cascade_grid(const blade::SectionProfile& section, const WallPatches& patches,
                             const SectionGridOptions& o, int wall_layers) {
  const CascadeOptions& cas = *o.cascade;
  const int n_in = cas.inlet_cells_pitchwise, n_out = cas.outlet_cells_pitchwise;
  const int n_per = (o.cells_around - n_in - n_out) / 2;

  const auto [a_min, a_max] = axial_range(section);
  if (!(section.le.x() < section.te.x()))
    throw InvalidGeometry("cascade: the section's LE must lie upstream (smaller a) of its TE");
  const MidLine mid(section.curve, a_min, a_max);
  const Stations st = passage_stations(section, mid, o, a_min, a_max);

  // Which periodic line faces the suction side (+1: the one at +b).
  const WallArc arc(section);
  const double S = arc.suction_length();
  const Eigen::Vector2d mid_suction = section.curve.point(arc.params({0.5 * S}).front());
  const PeriodicLines lines{mid, cas.pitch, mid_suction.y() > mid.y(mid_suction.x()) ? 1.0 : -1.0};

  std::vector<Eigen::Vector2d> outer = outer_nodes(lines, st, n_in, n_per, n_out);
  const OuterLoop loop = outer_loop(lines, st);
  const std::vector<double> s_wall = wall_positions(arc, patches, o, loop, outer_node_positions(loop, outer, n_in, n_per, n_out));
  BuiltGrid out;
  out.wall_params = arc.params(s_wall);
  out.wall_params.back() = out.wall_params.front() + section.curve.period();
  outer.push_back(outer.front());

  out.grid.blocks.push_back(o_grid_block(patches, o, wall_layers, out.wall_params, outer));
  out.wall_layers = wall_layers;
  add_inlet_outlet_blocks(out, lines, st, o, n_in, n_per, n_out);
  connect_cascade(out, o, cas.pitch, lines.up, n_in, n_per, n_out);
  make_right_handed(out, 0);
  return out;
}

}  // namespace cg::grid::detail
