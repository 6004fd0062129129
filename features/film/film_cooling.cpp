#include "features/film/film_cooling.hpp"

#include <algorithm>
#include <chrono>

#include "features/film/film_holes.hpp"
#include "features/film/film_rows.hpp"
#include "src/core/format.hpp"

namespace cg::features {

FilmPlan plan_film(const blade::BladeModel& model, FilmCavity& cavity, const FilmCoolingDefinition& def) {
  require(cavity.target.model == &model, "film cooling: the cavity belongs to another blade model");
  FilmPlan plan;
  // The inserts' chambers first: an insert limits how far hole tools may reach into its chamber.
  for (std::size_t i = 0; i < def.inserts.size(); ++i) {
    const InsertDefinition& d = def.inserts[i];
    const std::string field = "inserts[" + std::to_string(i) + "]";
    const auto it = std::find_if(cavity.chambers.begin(), cavity.chambers.end(),
                                 [&](const InsertChamber& c) { return c.number == d.chamber; });
    if (it == cavity.chambers.end())
      throw FilmInputError(field + ".chamber", "insert_" + std::to_string(i + 1) + ": there is no chamber_" +
                                                   std::to_string(d.chamber) + " (" + std::to_string(cavity.chambers.size()) +
                                                   " chambers)");
    for (std::size_t j = 0; j < i; ++j)
      if (def.inserts[j].chamber == d.chamber)
        throw FilmInputError(field + ".chamber", "chamber_" + std::to_string(d.chamber) + " already holds insert_" + std::to_string(j + 1));
    check_insert_input(*it, d, static_cast<int>(i) + 1, field);
    plan.insert_chambers.push_back(static_cast<std::size_t>(it - cavity.chambers.begin()));
  }
  limit_reach_by_inserts(cavity.target, def.inserts);
  if (def.has_holes()) plan.holes = analyse_film_holes(cavity.target, place_film_holes(model, def), def.limits);
  return plan;
}

FilmCoolingResult build_film_cooling(const blade::BladeModel& model, const brep::NamedShape& blade, const FilmCavity& cavity,
                                     FilmPlan plan, const FilmCoolingDefinition& def, const FeatureOptions& stage) {
  require(cavity.target.model == &model && plan.insert_chambers.size() == def.inserts.size(),
          "film cooling: the plan belongs to another blade model or definition");
  ProgressSink* const progress = stage.progress;
  FilmCoolingResult out;
  out.blade = blade;
  FilmReport& rep = out.report;
  rep.configured_min_ligament = def.limits.min_ligament;
  auto t0 = std::chrono::steady_clock::now();
  const auto lap = [&](const std::string& stage) {
    const auto t = std::chrono::steady_clock::now();
    rep.seconds.emplace_back(stage, std::chrono::duration<double>(t - t0).count());
    t0 = t;
  };

  std::vector<const InsertChamber*> insert_chambers;
  for (std::size_t k : plan.insert_chambers) insert_chambers.push_back(&cavity.chambers[k]);
  FilmHoleTools& tools = plan.holes;
  if (def.has_holes()) {
    add_hole_tools(tools);
    lap("hole_tools");
  }

  // Stop requests between the steps (the booleans and the gap measurement poll inside too).
  const auto poll = [&](const std::string& before) {
    if (progress && progress->stop_requested()) throw Cancelled(before, "before");
  };
  std::vector<InsertBuild> inserts;
  for (std::size_t i = 0; i < def.inserts.size(); ++i) {
    poll("insert_" + std::to_string(i + 1));
    inserts.push_back(build_insert(model, *insert_chambers[i], def.inserts[i], static_cast<int>(i) + 1,
                                   "inserts[" + std::to_string(i) + "]", progress, def.retries));
    lap("insert_" + std::to_string(i + 1));
  }

  // The holes cut in one verified boolean step.
  if (def.has_holes()) {
    poll("the film hole cut");
    BooleanOptions options = film_boolean_options(progress);
    options.verification = stage.verification;
    options.perturbed_retries = def.retries;
    FilmCutResult cut = cut_film_holes(blade, cavity.target, tools, options);
    out.blade = std::move(cut.blade);
    out.check = cut.check;
    out.blade_checked = cut.checked;
    out.holes_cut = true;
    const std::vector<std::pair<std::string, double>> seconds = rep.seconds;
    rep = std::move(cut.report);
    rep.configured_min_ligament = def.limits.min_ligament;
    rep.seconds.insert(rep.seconds.begin(), seconds.begin(), seconds.end());
    lap("hole_cut");
  }

  for (std::size_t i = 0; i < inserts.size(); ++i) {
    measure_insert(model, out.blade, inserts[i], *insert_chambers[i], def.inserts[i], progress);
    // The offsets are fitted within 1e-3 mm (inner_wall.hpp): the built gap and sheet must match within 5e-3.
    const InsertMeasure& m = inserts[i].measure;
    const double tol = 5e-3;
    if (m.measured_gap < m.gap - tol)
      throw FeatureFailure(m.name + ": the gap to the blade measures " + format_value_limit(m.measured_gap, m.gap, Allowed::near).value +
                           " mm on the built solids, configured " + format_value_limit(m.measured_gap, m.gap, Allowed::near).limit + " mm");
    if (std::abs(m.measured_sheet_min - m.sheet_thickness) > tol || std::abs(m.measured_sheet_max - m.sheet_thickness) > tol)
      throw FeatureFailure(m.name + ": the sheet measures " + format_number(m.measured_sheet_min) + " to " +
                           format_number(m.measured_sheet_max) + " mm on the built solid, configured " +
                           format_number(m.sheet_thickness) + " mm");
    rep.inserts.push_back(inserts[i].measure);
    rep.perturbed.insert(rep.perturbed.end(), inserts[i].perturbed.begin(), inserts[i].perturbed.end());
    for (const auto& [stage, s] : inserts[i].seconds) rep.seconds.emplace_back(inserts[i].body.name + "_" + stage, s);
    out.inserts.push_back(inserts[i].body);
    out.insert_checks.push_back(inserts[i].check);
  }
  if (!inserts.empty()) lap("insert_checks");
  return out;
}

}  // namespace cg::features
