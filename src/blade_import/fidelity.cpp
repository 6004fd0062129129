#include "src/blade_import/fidelity.hpp"

#include <cmath>

#include "src/algo/project_point_surface.hpp"
#include "src/blade_import/channel_side.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/parallel.hpp"

namespace cg::blade_import {
namespace {

constexpr double kFar = 1.0;  // mm

struct Probe {
  Eigen::Vector3d point;
  std::size_t section;
  int kind;  // 0 at a point, 1 between points, 2 towards the next section, 3 on an input face
  int line;  // file line (kind 3: the face's number)
  double distance = -1;  // < 0: outside the flow path
};

void add(blade::DeviationFigures& f, double d) {
  f.max = std::max(f.max, d);
  f.rms += d * d;  // sum of squares until finished
  ++f.points;
}

void finish(blade::DeviationFigures& f) { f.rms = f.points > 0 ? std::sqrt(f.rms / static_cast<double>(f.points)) : 0; }

// The foot of P on the surface by Newton's method from (u, v) (the previous probe's foot: probes come
// in order along the sections): true when it converged inside the v domain. Its distance is never
// below the global minimum, so a figure within the tolerance found this way is one the global
// projection would accept too; anything else goes to the global projection.
bool local_foot(const BSplineSurface<3>& s, const Eigen::Vector3d& P, double& u, double& v, double& dist) {
  const double period = s.last_u() - s.first_u();
  for (int it = 0; it < 25; ++it) {
    const auto d = s.derivatives<2>(u, v);
    const Eigen::Vector3d F = d.S() - P;
    const Eigen::Vector2d g(d.S_u().dot(F), d.S_v().dot(F));
    Eigen::Matrix2d H;
    H << d.S_u().squaredNorm() + d.S_uu().dot(F), d.S_u().dot(d.S_v()) + d.S_uv().dot(F),
        d.S_u().dot(d.S_v()) + d.S_uv().dot(F), d.S_v().squaredNorm() + d.S_vv().dot(F);
    if (H.determinant() <= 0 || H(0, 0) <= 0) return false;
    const Eigen::Vector2d step = -H.inverse() * g;
    u += step.x();
    v += step.y();
    if (s.is_periodic_u()) u = s.first_u() + std::fmod(std::fmod(u - s.first_u(), period) + period, period);
    if (v <= s.first_v() || v >= s.last_v() || (!s.is_periodic_u() && (u <= s.first_u() || u >= s.last_u()))) return false;
    if (std::abs(step.x()) < 1e-13 && std::abs(step.y()) < 1e-13) {
      dist = (s.point(u, v) - P).norm();
      return true;
    }
  }
  return false;
}

std::vector<Probe> probes(const ImportedBlade& b, const InputSurface& surf) {
  std::vector<Probe> out;
  for (const SurfaceSample& p : b.surface_samples) out.push_back({p.point, p.section, 3, p.face});
  for (std::size_t k = 0; k < surf.sections(); ++k) {
    const auto& pts = surf.loop_points(k);
    const auto& par = surf.point_params(k);
    const auto& lines = surf.loop_lines(k);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      out.push_back({pts[i], k, 0, lines[i]});
      const double next = i + 1 < par.size() ? par[i + 1] : par[0] + 1;
      double u = 0.5 * (par[i] + next);
      u -= std::floor(u);
      out.push_back({surf.section_curve(k).point(u), k, 1, lines[i]});
    }
    if (k + 1 < surf.sections()) {
      const double tau = 0.5 * (surf.section_tau(k) + surf.section_tau(k + 1));
      for (int j = 0; j < surf.loop_size(); ++j) out.push_back({surf.point(j, tau), k, 2, lines.front()});
    }
  }
  return out;
}

}  // namespace

blade::ImportRecord measure_fidelity(const ImportedBlade& b, const SlicedBlade& sliced, const blade::BladeModel& model,
                                     double tolerance) {
  const InputSurface& surf = *sliced.surface;
  std::vector<Probe> ps = probes(b, surf);
  const int workers = std::min(parallel_workers(), 4);
  std::vector<std::unique_ptr<SurfaceProjector>> proj;
  std::vector<std::unique_ptr<ChannelSide>> sides;
  for (int w = 0; w < workers; ++w) {
    proj.push_back(std::make_unique<SurfaceProjector>(model.surface));
    sides.push_back(model.net ? std::make_unique<ChannelSide>(*model.net) : std::make_unique<ChannelSide>(model.span_length));
  }
  std::vector<Eigen::Vector2d> seed(static_cast<std::size_t>(workers), Eigen::Vector2d(-1, -1));
  parallel_for(static_cast<int>(ps.size()), workers, [&](int i, int w) {
    Probe& p = ps[static_cast<std::size_t>(i)];
    const auto wi = static_cast<std::size_t>(w);
    if (sides[wi]->offset(p.point, 0) < 0 || sides[wi]->offset(p.point, 1) > 0) return;
    double u = seed[wi].x(), v = seed[wi].y(), d = 0;
    if (u >= 0 && local_foot(model.surface, p.point, u, v, d) && d <= tolerance) {
      p.distance = d;
      seed[wi] = Eigen::Vector2d(u, v);
      return;
    }
    // Only distances up to kFar are sought (patches farther away are skipped at once): beyond it the
    // exact figure does not matter, the import is refused anyway.
    const SurfaceProjection f = proj[wi]->project(p.point, kFar);
    p.distance = f.found ? f.distance : kFar;
    if (f.found) seed[wi] = Eigen::Vector2d(f.u, f.v);
  });
  blade::ImportRecord r;
  r.format = "geomturbo";
  r.file = b.file;
  r.row = b.kind == RowKind::Cascade ? "cascade" : "annular";
  r.number_of_blades = b.number_of_blades;
  r.tip_gap_le = b.tip_gap_le;
  r.tip_gap_te = b.tip_gap_te;
  r.tolerance = tolerance;
  r.cuts = static_cast<int>(sliced.spans.size());
  r.samples_per_side = surf.samples_per_side();
  for (std::size_t k = 0; k < surf.sections(); ++k)
    r.sections.push_back({static_cast<int>(k + 1), b.sections[k].line, {}, {}, {}, {}});
  const Probe* worst = nullptr;
  for (const Probe& p : ps) {
    if (p.distance < 0) continue;
    auto& s = r.sections[p.section];
    add(p.kind == 0 ? s.at_points : p.kind == 1 ? s.between_points : p.kind == 2 ? s.to_next : s.on_faces, p.distance);
    add(r.overall, p.distance);
    if (!worst || p.distance > worst->distance) worst = &p;
  }
  for (auto& s : r.sections) {
    finish(s.at_points);
    finish(s.between_points);
    finish(s.to_next);
    finish(s.on_faces);
  }
  finish(r.overall);
  if (worst && worst->distance > tolerance && worst->kind == 3)
    throw InvalidGeometry(b.file + ": face " + std::to_string(worst->line) + ": the built blade lies " +
                          (worst->distance >= kFar ? "more than " : "") + format_number(worst->distance) +
                          " mm from the input face at (" + format_number(worst->point.x()) + ", " + format_number(worst->point.y()) +
                          ", " + format_number(worst->point.z()) + ") mm, between the cuts " + std::to_string(worst->section + 1) +
                          " and " + std::to_string(worst->section + 2) + ", more than blade.import.tolerance " +
                          format_number(tolerance) + " mm (more cuts, blade.import.spans, follow the faces closer)");
  if (worst && worst->distance > tolerance) {
    static const char* where[] = {"at its point on this line", "half-way after its point on this line",
                                  "half-way to the next section"};
    throw InvalidGeometry(b.file_of(worst->section) + ":" + std::to_string(worst->line) + ": section " + std::to_string(worst->section + 1) +
                          ": the built blade lies " + (worst->distance >= kFar ? "more than " : "") +
                          format_number(worst->distance) + " mm from the input " +
                          where[worst->kind] + ", more than blade.import.tolerance " + format_number(tolerance) +
                          " mm (sections too far apart or too sparse for a smooth blade through them?)");
  }
  return r;
}

}  // namespace cg::blade_import
