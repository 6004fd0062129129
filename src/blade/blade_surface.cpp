#include "src/blade/blade_surface.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/blade/section_family.hpp"
#include "src/blade/surface_iso.hpp"
#include "src/blade/wall_fit.hpp"
#include "src/core/error.hpp"

namespace cg::blade {
namespace {


std::string section_name(std::size_t k) { return "section " + std::to_string(k); }

void validate(const BladeDefinition& def) {
  const BladeOptions& opt = def.options;
  require(opt.overbuild > 0 && opt.overbuild <= 0.5, "blade options: overbuild must be in (0, 0.5] of span, got " +
                                                         format_number(opt.overbuild));
  require(opt.chordwise_samples >= 8 && opt.chordwise_samples <= 2000,
          "blade options: chordwise_samples must be in [8, 2000], got " + std::to_string(opt.chordwise_samples));
  require(opt.surface_tolerance >= 1e-5 && opt.surface_tolerance <= 0.1,
          "blade options: surface_tolerance must be in [1e-5, 0.1] mm, got " + format_number(opt.surface_tolerance));
  require(opt.seam >= -1 && opt.seam <= 1, "blade options: seam must be a chordwise coordinate in [-1, 1], got " +
                                               format_number(opt.seam));
  require(!def.sections.empty(), "blade: at least one section is needed");
  for (std::size_t k = 0; k < def.sections.size(); ++k) {
    const SectionPlacement& p = def.sections[k].placement;
    require(p.span >= 0 && p.span <= 1, section_name(k) + ": span must be in [0, 1], got " + format_number(p.span));
    require(k == 0 || p.span > def.sections[k - 1].placement.span,
            section_name(k) + ": section spans must increase strictly, got " + format_number(p.span) + " after " +
                format_number(def.sections[k - 1].placement.span));
    require(p.scale > 0, section_name(k) + ": scale must be > 0, got " + format_number(p.scale));
  }
}

SectionDiagnostics diagnose(const SectionProfile& p, double span) {
  SectionDiagnostics d;
  d.span = span;
  d.chord = p.chord();
  d.stagger_deg = std::atan2(p.chord_direction.y(), p.chord_direction.x()) * 180 / kPi;
  d.area = std::abs(section_properties(p.curve).area);
  d.le_circle = p.le_circle;
  d.te_circle = p.te_circle;
  d.le_circle_points = p.le_circle_points;
  d.te_circle_points = p.te_circle_points;
  d.le_arc = p.le_arc;
  d.te_arc = p.te_arc;
  return d;
}

}  // namespace

BladeModel build_blade(const BladeDefinition& def) {
  validate(def);
  const BladeOptions& opt = def.options;
  BladeModel model;
  model.options = opt;
  const bool straight = std::holds_alternative<StraightFlowPath>(def.flow_path);
  double span_mm = 0;
  if (straight) {
    span_mm = std::get<StraightFlowPath>(def.flow_path).span;
    require(span_mm > 0, "straight vane: span must be > 0 mm, got " + format_number(span_mm));
    model.trim.straight = true;
    model.trim.hub_z = 0;
    model.trim.casing_z = span_mm;
    model.span_length = span_mm;
  } else {
    model.net.emplace(std::get<MeridionalFlowPath>(def.flow_path).net);
    require(model.net->leading_edge().has_value(),
            "meridional blade: the net needs a leading-edge line to place the sections");
    model.trim.straight = false;
    model.trim.hub = model.net->hub().curve();
    model.trim.casing = model.net->casing().curve();
    const auto& cuts = model.net->leading_edge()->cuts;
    model.span_length = (cuts.back().point - cuts.front().point).norm();
  }

  auto family = std::make_shared<const detail::SectionFamily>(def, model.net, span_mm);
  detail::WallFitOptions wo;
  wo.tolerance = opt.surface_tolerance;
  wo.min_samples_per_side = opt.chordwise_samples;
  wo.overbuild = opt.overbuild;
  detail::WallFit fit = detail::fit_wall(*family, wo);

  model.surface = std::move(fit.surface);
  model.u_le = family->u_le();
  model.u_te = family->u_te();
  model.seam = opt.seam;
  model.skinned_spans = fit.spans;
  model.surface_tolerance = opt.surface_tolerance;
  model.surface_deviation = fit.max_deviation;
  model.surface_check_points = fit.checked_points;
  model.section_spans = family->defined_spans();
  model.profiles = family->defined_profiles();
  for (std::size_t k = 0; k < model.section_spans.size(); ++k) {
    model.section_curves.push_back(detail::iso_curve_v(model.surface, model.section_spans[k]));
    if (k < def.sections.size()) model.diagnostics.push_back(diagnose(model.profiles[k], def.sections[k].placement.span));
  }
  model.family = std::move(family);
  return model;
}

}  // namespace cg::blade
