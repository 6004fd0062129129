#include "src/pipeline/report.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/blade/section.hpp"
#include "src/core/constants.hpp"
#include "src/core/parallel.hpp"
#include "src/pipeline/sha256.hpp"
#include "export/version.hpp"

namespace cg::pipeline {
namespace {

using json = nlohmann::ordered_json;

constexpr double kDegPerRad = 180 / kPi;

json xyz(const Eigen::Vector3d& p) { return json::array({p.x(), p.y(), p.z()}); }
json ab(const Eigen::Vector2d& p) { return json::array({p.x(), p.y()}); }

// Section k of the built model. The built chord is the straight distance between the LE and TE of the
// 3D section curve (on a meridional path the section is scaled to fit between the LE and TE lines, so
// it differs from the profile's own chord).
// The blade model's per-section diagnostics (issue 8 items 2 and 5): the edge circles found (and
// whether the profile follows them as exact arcs); the surface's tolerance, achieved deviation and pole
// counts are in blade_surface. The 3D section's LE and TE are at the surface parameters u_le, u_te.
// An imported blade's sections are its cuts (point sections made by the import, at the model's spans).
json section_entry(const config::Config& c, const blade::BladeModel& m, std::size_t i) {
  json e;
  if (c.blade_import) {
    e = json{{"span", i < m.section_spans.size() ? m.section_spans[i] : 0.0}, {"kind", "points"}};
  } else {
    const auto& def = c.blade.sections[i];
    const bool points = std::holds_alternative<blade::PointSectionDefinition>(def.shape);
    e = json{{"span", def.placement.span}, {"kind", points ? "points" : "parametric"}};
    if (points && !std::get<blade::PointSectionDefinition>(def.shape).file.empty())
      e["file"] = std::get<blade::PointSectionDefinition>(def.shape).file;
  }
  if (i >= m.profiles.size() || i >= m.section_curves.size()) return e;
  const blade::SectionProfile& p = m.profiles[i];
  const BSplineCurve<3>& curve = m.section_curves[i];
  const Eigen::Vector3d le = curve.point(curve.check_param(m.u_le)), te = curve.point(curve.check_param(m.u_te));
  const blade::SectionProperties props = blade::section_properties(p.curve);
  e["chord_mm"] = (te - le).norm();
  e["leading_edge_mm"] = xyz(le);
  e["trailing_edge_mm"] = xyz(te);
  e["profile"] = {{"chord_mm", p.chord()},
                  {"stagger_deg", std::atan2(p.chord_direction.y(), p.chord_direction.x()) * kDegPerRad},
                  {"area_mm2", std::abs(props.area)},
                  {"perimeter_mm", props.perimeter},
                  {"leading_edge", ab(p.le)},
                  {"trailing_edge", ab(p.te)},
                  {"poles", p.curve.num_period_poles()}};
  e["poles_3d"] = curve.num_period_poles();
  if (i < m.diagnostics.size()) {
    const blade::SectionDiagnostics& d = m.diagnostics[i];
    const auto circle = [](const blade::EdgeCircle& k, int points, bool arc) {
      json j{{"centre_mm", ab(k.centre)}, {"radius_mm", k.radius}, {"points_on_circle", points}, {"exact_arc", arc}};
      return j;
    };
    e["le_circle"] = circle(d.le_circle, d.le_circle_points, d.le_arc);
    e["te_circle"] = circle(d.te_circle, d.te_circle_points, d.te_arc);
  }
  return e;
}

}  // namespace

json deviation(const blade::DeviationFigures& d) { return json{{"max_mm", d.max}, {"rms_mm", d.rms}, {"points", d.points}}; }

// blade.import: the file, its blade count and tip gap, and the fidelity per imported section.
json import_entry(const blade::ImportRecord& r) {
  json sections = json::array();
  for (const blade::ImportedSectionFidelity& s : r.sections) {
    sections.push_back({{"section", s.section}, {"line", s.line}, {"at_points", deviation(s.at_points)},
                        {"between_points", deviation(s.between_points)}, {"to_next_section", deviation(s.to_next)}});
    if (r.format == "step" || r.format == "iges") sections.back()["on_input_faces"] = deviation(s.on_faces);
  }
  return json{{"format", r.format}, {"file", r.file}, {"row", r.row},
              {"number_of_blades", r.number_of_blades > 0 ? json(r.number_of_blades) : json()},
              {"tip_gap_mm", {{"leading_edge", r.tip_gap_le}, {"trailing_edge", r.tip_gap_te}}},
              {"tolerance_mm", r.tolerance}, {"cuts", r.cuts}, {"samples_per_side", r.samples_per_side},
              {"deviation", deviation(r.overall)}, {"sections", sections}};
}

nlohmann::ordered_json report_model(const config::Config& c, const blade::BladeModel& m) {
  json sections = json::array();
  for (std::size_t i = 0; i < config::section_count(c); ++i) sections.push_back(section_entry(c, m, i));
  const auto& s = m.surface;
  nlohmann::ordered_json out = json{{"name", c.name},
              {"description", c.description},
              {"flow_path", m.trim.straight ? "straight" : "meridional"},
              {"span_length_mm", m.span_length},
              {"sections", sections},
              {"blade_surface",
               {{"degree_u", s.degree_u()},
                {"degree_v", s.degree_v()},
                {"poles_u", m.poles_u()},
                {"poles_v", m.poles_v()},
                {"rational", s.is_rational()},
                {"tolerance_mm", m.surface_tolerance},
                {"achieved_deviation_mm", m.surface_deviation},
                {"check_points", m.surface_check_points},
                {"skinned_sections", m.skinned_spans.size()},
                {"seam_chordwise", m.seam}}},
              {"overbuild", m.options.overbuild},
              {"step_schema", c.output.step_schema},
              {"iges_mode", c.output.iges_mode},
              {"config", c.source}};
  if (m.imported) out["import"] = import_entry(*m.imported);
  return out;
}

void hash_inputs(Sha256& h, const nlohmann::json& document, const config::Config& c) {
  // Each part is length-prefixed so that moving bytes between parts changes the hash.
  const auto part = [&](const std::string& s) {
    h.update(std::to_string(s.size()) + ":");
    h.update(s);
  };
  part(document.dump());
  std::vector<std::string> files;
  for (const auto& s : c.blade.sections) {
    const auto* p = std::get_if<blade::PointSectionDefinition>(&s.shape);
    if (p && !p->file.empty()) files.push_back(p->file);
  }
  if (c.blade_import)  // a changed import file changes the blade
    files.insert(files.end(), c.blade_import->files.begin(), c.blade_import->files.end());
  files.insert(files.end(), c.cooling.source_files.begin(), c.cooling.source_files.end());
  for (const std::string& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    part(in ? bytes.str() : std::string("<unreadable>"));
  }
}

std::string input_hash(const config::Config& c) {
  Sha256 h;
  hash_inputs(h, c.source, c);
  return "sha256:" + h.hex_digest();
}

io::ReportContent report_content(const config::Config& c, const BuildResult& r, const std::vector<std::string>& outputs,
                                 const std::vector<StageTiming>& timings) {
  io::ReportContent rc;
  rc.version = io::tool_version();
  rc.input_hash = input_hash(c);
  if (!r.checks.empty()) rc.check = r.checks.front();
  if (!r.part.empty()) rc.face_names = brep::count_face_names(r.part.front().geometry);
  rc.warnings = r.warnings;
  rc.model = report_model(c, r.model);
  rc.model["source"] = c.source_file.empty() ? "<built-in example>" : c.source_file;
  if (r.cooling) rc.model["cooling"] = r.cooling->to_json();
  if (r.film) rc.model["cooling"]["film"] = r.film->to_json();
  for (const StageTiming& s : timings) rc.timings_s[s.stage] = s.seconds;
  rc.threads = parallel_workers();
  rc.outputs = outputs;
  // "solid" describes the blade; "bodies" every body of the part (blade first, then inserts), so a
  // reader of the files (STEP solids, IGES shells, one .vtp per body) can check each one.
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.part.size() && i < r.checks.size(); ++i) {
    const brep::SolidCheck& k = r.checks[i];
    bodies.push_back({{"name", r.part[i].name},
                      {"valid", k.all_passed()},
                      {"volume_mm3", k.volume},
                      {"surface_area_mm2", k.area()},
                      {"face_count", k.face_count},
                      {"faces", brep::count_face_names(r.part[i].geometry)}});
  }
  rc.extra["bodies"] = bodies;
  // Tools a boolean step let in only after a perturbed retry (src/brep/boolean/boolean_retries.hpp).
  nlohmann::ordered_json perturbed = nlohmann::ordered_json::array();
  for (const auto* list : {r.cooling ? &r.cooling->perturbed : nullptr, r.film ? &r.film->perturbed : nullptr})
    for (std::size_t i = 0; list && i < list->size(); ++i)
      perturbed.push_back({{"feature", (*list)[i].feature}, {"change", (*list)[i].change},
                           {"geometry_changed", (*list)[i].geometry_changed}});
  // Which stages came from the stage cache: not a property of the model (the same with or without it).
  if (!r.stage_cache.empty()) {
    nlohmann::ordered_json uses = nlohmann::ordered_json::array();
    for (const StageCacheUse& u : r.stage_cache)
      uses.push_back({{"stage", u.stage}, {"outcome", StageCacheUse::name(u.outcome)}, {"key", u.key}});
    rc.extra["stage_cache"] = uses;
  }
  rc.extra["booleans"] = {{"allow_perturbation", c.cooling.passages.retries == features::PerturbedRetries::Any},
                          {"perturbed_tools", perturbed}};
  return rc;
}

}  // namespace cg::pipeline
