#include "src/config/config.hpp"

#include <algorithm>
#include <regex>
#include <fstream>
#include <limits>
#include <sstream>

#include "src/blade/meridional_net.hpp"
#include "src/blade/section.hpp"
#include "src/blade_import/geomturbo_reader.hpp"
#include "src/blade_import/section_table_reader.hpp"
#include "src/config/handoff_fields.hpp"
#include "src/config/json_document.hpp"
#include "src/config/json_fields.hpp"
#include "src/core/format.hpp"

namespace cg::config {
namespace {

const Range kAny{-HUGE_VAL, HUGE_VAL};

// Polyline of [x, r] points in mm, r > 0.
blade::MeridionalPolyline polyline(const Field& f, std::size_t min_points) {
  const std::size_t n = f.expect_array(min_points);
  blade::MeridionalPolyline out;
  for (std::size_t i = 0; i < n; ++i) {
    const Field p = f.item(i);
    p.expect_array(2, 2);
    out.emplace_back(p.item(0).number(kAny, "mm"), p.item(1).number(positive(), "mm"));
    // Points must run along the contour: an unsorted list would zig-zag and the interpolated curve fold.
    if (i >= 1 && out[i] == out[i - 1]) fail(p.path(), "coincides with the previous point");
    if (i >= 2 && (out[i] - out[i - 1]).dot(out[i - 1] - out[i - 2]) <= 0.0)
      fail(p.path(), "the contour turns back here (more than 90 deg between consecutive segments): list the "
                     "points in order along the contour");
  }
  return out;
}

blade::MeridionalNetDefinition meridional_net(const Field& f) {
  f.expect_object({"type", "hub", "casing", "streamlines", "leading_edge", "trailing_edge", "stations", "samples"});
  blade::MeridionalNetDefinition net;
  net.hub = polyline(f.at("hub"), 2);
  net.casing = polyline(f.at("casing"), 2);
  if (f.has("streamlines")) {
    const Field s = f.at("streamlines");
    const std::size_t n = s.expect_array(0);
    for (std::size_t i = 0; i < n; ++i) {
      const Field e = s.item(i);
      if (e.is_number()) {
        const double span = e.number(open(0, 1));
        if (!net.interpolated_spans.empty() && span <= net.interpolated_spans.back()) {
          const ValueLimitText t = format_value_limit(span, net.interpolated_spans.back(), Allowed::above);
          fail(e.path(), "streamline span fractions must be strictly increasing, got " + t.value + " after " + t.limit);
        }
        net.interpolated_spans.push_back(span);
        continue;
      }
      if (!e.is_object()) fail(e.path(), "must be a span fraction in (0, 1) or an object {\"span\", \"points\"}, got " +
                                              json_type_name(e.json()));
      e.expect_object({"span", "points"});
      const double span = e.at("span").number(open(0, 1));
      if (!net.streamline_spans.empty() && span <= net.streamline_spans.back()) {
        const ValueLimitText t = format_value_limit(span, net.streamline_spans.back(), Allowed::above);
        fail(e.path() + ".span", "explicit streamlines must be listed with strictly increasing span, got " + t.value + " after " + t.limit);
      }
      net.streamline_spans.push_back(span);
      net.streamlines.push_back(polyline(e.at("points"), 2));
    }
  }
  if (f.has("leading_edge")) net.leading_edge = polyline(f.at("leading_edge"), 2);
  if (f.has("trailing_edge")) net.trailing_edge = polyline(f.at("trailing_edge"), 2);
  if (f.has("stations")) {
    const Field s = f.at("stations");
    const std::size_t n = s.expect_array(0);
    for (std::size_t i = 0; i < n; ++i) net.stations.push_back(polyline(s.item(i), 2));
  }
  net.samples = f.integer_or("samples", net.samples, 16, 100000);
  return net;
}

std::variant<blade::StraightFlowPath, blade::MeridionalFlowPath> flow_path(const Field& f) {
  if (!f.is_object()) fail(f.path(), "must be an object, got " + json_type_name(f.json()));
  const int type = f.at("type").choice({"straight", "meridional"});
  if (type == 0) {
    f.expect_object({"type", "span"});
    return blade::StraightFlowPath{f.at("span").number(positive(1e5), "mm")};
  }
  return blade::MeridionalFlowPath{meridional_net(f)};
}

blade::LengthUnit length_unit(const Field& f) {
  static const blade::LengthUnit units[] = {blade::LengthUnit::Millimetre, blade::LengthUnit::Centimetre,
                                            blade::LengthUnit::Metre, blade::LengthUnit::Inch};
  return units[f.choice({"mm", "cm", "m", "in"})];
}

// [x, y] in a section's unit, returned in mm: finite in the unit is not enough (1e308 in overflows).
Eigen::Vector2d pair_in_mm(const Field& f, double mm_per_unit) {
  const Eigen::Vector2d p = f.pair();
  if (!std::isfinite(mm_per_unit * p.x()) || !std::isfinite(mm_per_unit * p.y()))
    fail(f.path(), "must be at most " + format_limit(std::numeric_limits<double>::max() / mm_per_unit, Allowed::below) +
                       " in magnitude in this unit (finite in mm), got [" + format_number(p.x()) + ", " +
                       format_number(p.y()) + "]");
  return mm_per_unit * p;
}

blade::PointSectionDefinition point_section(const Field& f, const std::filesystem::path& base_dir, PointSource& source) {
  source.field = f.path();
  f.expect_object({"file", "values", "unit", "le_index", "te_index", "suction_side", "le_radius", "te_radius",
                   "le_centre", "te_centre"});
  if (f.has("file") == f.has("values")) fail(f.path(), "needs exactly one of \"file\" and \"values\"");
  blade::PointSectionDefinition def;
  def.unit = f.has("unit") ? length_unit(f.at("unit")) : blade::LengthUnit::Millimetre;
  if (f.has("file")) {
    const Field file = f.at("file");
    std::filesystem::path p = file.string();
    if (p.is_relative()) p = base_dir / p;
    def.file = p.string();
    source.file = def.file;
    try {
      def.points = blade::read_section_points(def.file, def.unit, &source.lines);
    } catch (const InvalidGeometry& e) {
      fail(file.path(), e.what());
    }
  } else {
    const Field values = f.at("values");
    const std::size_t n = values.expect_array(4);
    const double k = blade::millimetres_per(def.unit);
    for (std::size_t i = 0; i < n; ++i) def.points.push_back(pair_in_mm(values.item(i), k));
  }
  const int last = static_cast<int>(def.points.size()) - 1;
  def.le_index = f.integer_or("le_index", -1, -1, last);
  def.te_index = f.integer_or("te_index", -1, -1, last);
  if (f.has("suction_side")) {
    static const blade::SuctionSide sides[] = {blade::SuctionSide::Longer, blade::SuctionSide::CounterClockwise,
                                               blade::SuctionSide::Clockwise};
    def.suction_side = sides[f.at("suction_side").choice({"longer", "counter_clockwise", "clockwise"})];
  }
  // Edge-circle hints, in the section's unit.
  const double k = blade::millimetres_per(def.unit);
  if (f.has("le_radius")) def.le_radius = k * f.at("le_radius").number(positive(1e5));
  if (f.has("te_radius")) def.te_radius = k * f.at("te_radius").number(positive(1e5));
  if (f.has("le_centre")) def.le_centre = pair_in_mm(f.at("le_centre"), k);
  if (f.has("te_centre")) def.te_centre = pair_in_mm(f.at("te_centre"), k);
  return def;
}

blade::ParametricSectionDefinition parametric_section(const Field& f) {
  f.expect_object({"chord", "stagger_deg", "inlet_metal_angle_deg", "outlet_metal_angle_deg", "max_thickness",
                   "max_thickness_position", "le_radius", "te_radius", "points_per_side"});
  blade::ParametricSectionDefinition d;
  d.chord = f.at("chord").number(positive(1e5), "mm");
  d.stagger_deg = f.at("stagger_deg").number(open(-90, 90), "deg");
  d.inlet_angle_deg = f.at("inlet_metal_angle_deg").number(open(-90, 90), "deg");
  d.outlet_angle_deg = f.at("outlet_metal_angle_deg").number(open(-90, 90), "deg");
  d.max_thickness = f.at("max_thickness").number(open(0, d.chord), "mm (0 < max_thickness < chord)");
  d.max_thickness_position = f.number_or("max_thickness_position", d.max_thickness_position, closed(0.1, 0.9));
  const Range radius = open(0, d.max_thickness / 2);
  d.le_radius = f.at("le_radius").number(radius, "mm (0 < radius < max_thickness / 2)");
  d.te_radius = f.at("te_radius").number(radius, "mm (0 < radius < max_thickness / 2)");
  d.points_per_side = f.integer_or("points_per_side", d.points_per_side, 8, 2000);
  return d;
}

blade::BladeSectionDefinition section(const Field& f, const std::filesystem::path& base_dir, PointSource& source) {
  f.expect_object({"span", "points", "parametric", "rotation_deg", "scale", "offset", "theta_deg"});
  if (f.has("points") == f.has("parametric")) fail(f.path(), "needs exactly one of \"points\" and \"parametric\"");
  blade::BladeSectionDefinition s;
  if (f.has("points"))
    s.shape = point_section(f.at("points"), base_dir, source);
  else
    s.shape = parametric_section(f.at("parametric"));
  auto& p = s.placement;
  p.span = f.at("span").number(closed(0, 1));
  p.rotation_deg = f.number_or("rotation_deg", 0, closed(-180, 180), "deg");
  p.scale = f.number_or("scale", 1, positive(100));
  p.theta_deg = f.number_or("theta_deg", 0, closed(-180, 180), "deg");
  if (f.has("offset")) p.offset = f.at("offset").pair();
  return s;
}

blade::BladeOptions blade_options(const Field& f) {
  f.expect_object({"overbuild", "chordwise_samples", "stacking", "surface_tolerance", "seam", "import"});
  blade::BladeOptions o;
  // > 0: the solid is cut out of the over-built surface by the hub and casing trims.
  o.overbuild = f.number_or("overbuild", o.overbuild, positive(0.5));
  o.chordwise_samples = f.integer_or("chordwise_samples", o.chordwise_samples, 8, 2000);
  o.surface_tolerance = f.number_or("surface_tolerance", o.surface_tolerance, closed(1e-5, 0.1), "mm");
  o.seam = f.number_or("seam", o.seam, closed(-1, 1));
  if (f.has("stacking")) {
    static const blade::StackingPoint points[] = {blade::StackingPoint::LeadingEdge, blade::StackingPoint::Centroid,
                                                  blade::StackingPoint::TrailingEdge};
    o.stacking = points[f.at("stacking").choice({"leading_edge", "centroid", "trailing_edge"})];
  }
  return o;
}

std::string resolved(const Field& f, const std::filesystem::path& base_dir) {
  std::filesystem::path p = f.string();
  if (p.is_relative()) p = base_dir / p;
  return p.string();
}

// blade.import's file(s), read for their syntax only (a STEP / IGES file only found readable: its reader
// is OCCT's); build_model cuts the blade (imported_model.cpp).
void read_import_files(const Field& f, const std::filesystem::path& base_dir, BladeImport& im) {
  const bool tables = im.format == "sections";
  for (const char* key : {"file", "files", "frame", "unit"})
    if (f.has(key) && (std::string(key) == "file") == tables)
      fail(f.path() + "." + key, "is not given with format \"" + im.format + "\" (" +
                                     (tables ? "files, frame and unit" : "file") + " instead)");
  try {
    if (im.format == "step" || im.format == "iges") {  // read and cut by build_model (OCCT)
      im.field = f.path() + ".file";
      im.files = {resolved(f.at("file"), base_dir)};
      if (!std::ifstream(im.files[0], std::ios::binary)) fail(im.field, "cannot read " + im.files[0]);
      return;
    }
    if (!tables) {
      im.field = f.path() + ".file";
      im.files = {resolved(f.at("file"), base_dir)};
      im.blade = std::make_shared<const blade_import::ImportedBlade>(blade_import::read_geomturbo(im.files[0]));
      return;
    }
    im.field = f.path() + ".files";
    im.frame = f.at("frame").choice({"xyz", "xrtheta"}) == 0 ? blade_import::TableFrame::Xyz : blade_import::TableFrame::XRTheta;
    const double k = blade::millimetres_per(f.has("unit") ? length_unit(f.at("unit")) : blade::LengthUnit::Millimetre);
    const Field files = f.at("files");
    const std::size_t n = files.expect_array(2);
    for (std::size_t i = 0; i < n; ++i) {
      im.files.push_back(resolved(files.item(i), base_dir));
      im.field = files.item(i).path();
      im.tables.push_back(blade_import::read_section_table(im.files.back(), im.frame, k));
    }
    im.field = f.path() + ".files";
  } catch (const InvalidGeometry& e) {
    fail(im.field, e.what());
  }
}

// blade.import: the format, the options and the file(s).
void import_blade(const Field& f, const std::filesystem::path& base_dir, Config& c) {
  f.expect_object({"format", "file", "files", "frame", "unit", "tolerance", "spans", "samples_per_side", "edges"});
  static const char* formats[] = {"geomturbo", "sections", "step", "iges"};
  BladeImport im;
  im.format = formats[f.at("format").choice({"geomturbo", "sections", "step", "iges"})];
  im.options.tolerance = f.number_or("tolerance", im.options.tolerance, closed(1e-4, 1), "mm");
  im.options.spans = f.integer_or("spans", 0, 0, 201);
  if (im.options.spans == 1) fail(f.path() + ".spans", "must be 0 (automatic) or in [2, 201], got 1");
  im.options.samples_per_side = f.integer_or("samples_per_side", 0, 0, 2000);
  if (im.options.samples_per_side > 0 && im.options.samples_per_side < 8)
    fail(f.path() + ".samples_per_side", "must be 0 (automatic) or in [8, 2000]");
  if (f.has("edges")) {
    if (im.format == "geomturbo")
      fail(f.path() + ".edges", "is only for \"sections\", \"step\" and \"iges\" (a geomTurbo file's sides give its LE and TE)");
    im.options.edges = f.at("edges").choice({"centre_line", "camber_line"}) == 0 ? blade::EdgeRule::CentreLine
                                                                               : blade::EdgeRule::CamberLine;
  }
  read_import_files(f, base_dir, im);
  im.cuts = blade_import::cut_count(im.options, im.blade ? im.blade->sections.size() : im.tables.size());
  c.blade_import = std::move(im);
}

// coolant.sinks.rows names exit rows: film_row_<k>, showerhead_<k>, te_slots. A row of that form the
// cooling section does not have (a variant with fewer rows than the one the coolant section was written
// for) has no exit to apply to; any other name is refused, naming the rows this blade has.
void check_sink_rows(const CoolantConfig& coolant, const CoolingConfig& cooling) {
  std::vector<std::string> rows;
  for (std::size_t k = 1; k <= cooling.film.rows.size(); ++k) rows.push_back("film_row_" + std::to_string(k));
  if (cooling.film.showerhead)
    for (int k = 1; k <= cooling.film.showerhead->rows; ++k) rows.push_back("showerhead_" + std::to_string(k));
  if (cooling.passages.core && cooling.passages.core->trailing_edge) rows.push_back("te_slots");
  static const std::regex row_name("(film_row|showerhead)_[1-9][0-9]*|te_slots");
  for (const auto& [name, p] : coolant.sink_by_row)
    if (!std::regex_match(name, row_name)) {
      std::string known;
      for (const std::string& r : rows) known += (known.empty() ? "" : ", ") + r;
      fail("coolant.sinks.rows." + name, "is no exit row name (film_row_<k>, showerhead_<k>, te_slots; this blade's: " +
                                             (known.empty() ? std::string("none") : known) + ")");
    }
}

}  // namespace

Config parse_config(const nlohmann::json& document, const std::filesystem::path& base_dir, const std::string& default_name) {
  const Field root(document, "");
  root.expect_object({"$schema", "name", "description", "units", "flow_path", "sections", "blade", "output", "mesh",
                      "grid", "cooling", "booleans", "coolant"});
  Config c;
  c.source = document;
  c.name = root.has("name") ? root.at("name").string() : default_name;
  if (root.has("description")) c.description = root.at("description").string();
  root.at("units").choice({"mm"});
  if (root.has("blade")) c.blade.options = blade_options(root.at("blade"));
  if (root.has("blade") && root.at("blade").has("import")) {
    if (root.has("sections")) fail("sections", "is not given with blade.import (the imported file gives the blade's sections)");
    import_blade(root.at("blade").at("import"), base_dir, c);
    if (c.blade_import->format == "geomturbo") {
      if (root.has("flow_path"))
        fail("flow_path", "is not given with blade.import format \"geomturbo\" (its CHANNEL gives the hub and casing)");
    } else {
      if (!root.has("flow_path"))
        fail("flow_path", "is required with blade.import format \"" + c.blade_import->format +
                              "\" (the hub and casing the imported blade is cut at)");
      c.blade.flow_path = flow_path(root.at("flow_path"));
      if (c.blade_import->frame == blade_import::TableFrame::XRTheta && std::holds_alternative<blade::StraightFlowPath>(c.blade.flow_path))
        fail("blade.import.frame", "\"xrtheta\" needs a meridional flow_path (a straight one's sections are x y z)");
    }
  } else {
    c.blade.flow_path = flow_path(root.at("flow_path"));
  }
  const Field sections = c.blade_import ? root : root.at("sections");
  const std::size_t n = c.blade_import ? 0 : sections.expect_array(1);
  for (std::size_t i = 0; i < n; ++i) {
    c.point_sources.emplace_back();
    c.blade.sections.push_back(section(sections.item(i), base_dir, c.point_sources.back()));
    if (i > 0) {
      const double prev = c.blade.sections[i - 1].placement.span, cur = c.blade.sections[i].placement.span;
      if (cur <= prev) {
        const ValueLimitText t = format_value_limit(cur, prev, Allowed::above);
        fail(sections.item(i).path() + ".span", "sections must have strictly increasing span: must be > " + t.limit + ", got " + t.value);
      }
    }
  }
  if (root.has("cooling")) c.cooling = parse_cooling(root.at("cooling"), base_dir);
  if (root.has("coolant")) c.coolant = parse_coolant(root.at("coolant"));
  if (root.has("booleans")) {
    const Field b = root.at("booleans");
    b.expect_object({"allow_perturbation"});
    if (!b.boolean_or("allow_perturbation", true))
      c.cooling.passages.retries = c.cooling.film.retries = features::PerturbedRetries::SameGeometry;
  }
  c.output.product_name = c.name;
  if (root.has("output")) {
    const Field out = root.at("output");
    out.expect_object({"formats", "step_schema", "iges_mode", "product_name", "stl_deflection", "stl_angular_deflection_deg",
                       "section_spans"});
    if (out.has("formats")) {
      const Field formats = out.at("formats");
      const std::size_t n = formats.expect_array(0);
      std::vector<std::string> names;
      for (std::size_t i = 0; i < n; ++i) names.push_back(formats.item(i).string());
      c.output.formats = parse_output_formats(names, formats.path());
    }
    if (out.has("step_schema"))
      c.output.step_schema = out.at("step_schema").choice({"AP214", "AP242"}) == 1 ? "AP242" : "AP214";
    if (out.has("iges_mode"))
      c.output.iges_mode = out.at("iges_mode").choice({"faces", "brep"}) == 1 ? "brep" : "faces";
    if (out.has("product_name")) c.output.product_name = out.at("product_name").string();
    read_handoff_output_fields(out, c.output);
  }
  // The flow network is written by default when the config has cooling and its boundary conditions.
  const bool formats_given = root.has("output") && root.at("output").has("formats");
  if (c.coolant && !c.cooling.empty() && !formats_given) {
    c.output.formats.clear();
    for (const OutputFormatInfo& f : kOutputFormats)
      if (f.by_default == DefaultOutput::Written || f.format == OutputFormat::Network) c.output.formats.push_back(f.format);
  }
  if (c.coolant && !c.cooling.empty()) check_sink_rows(*c.coolant, c.cooling);  // without cooling it is not used
  if (has_format(c.output.formats, OutputFormat::Network)) {
    if (!c.coolant) fail("coolant", "required when output.formats lists \"network\" (supply, sinks: docs/configuration.md)");
    if (c.cooling.empty()) fail("output.formats", "\"network\" needs a \"cooling\" section (the coolant circuit is its passages)");
  }
  if (root.has("mesh")) c.mesh = mesh_config(root.at("mesh"));
  if (root.has("grid")) c.grid = parse_grid_config(root.at("grid"), section_count(c));
  return c;
}

std::size_t section_count(const Config& config) {
  return config.blade_import ? static_cast<std::size_t>(config.blade_import->cuts) : config.blade.sections.size();
}

Config parse_config_text(const std::string& text, const std::filesystem::path& base_dir, const std::string& default_name,
                         const std::string& source_name) {
  return parse_config(parse_json_document(text, source_name), base_dir, default_name);
}

Config load_config_file(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (!fs::exists(st)) throw ConfigError("config: " + file.string() + " does not exist");
  if (fs::is_directory(st)) {
    std::string found;
    for (const auto& e : fs::directory_iterator(file, ec))
      if (e.path().extension() == ".json") found += (found.empty() ? "" : ", ") + e.path().filename().string();
    throw ConfigError("config: " + file.string() + " is a directory, not a config file" +
                      (found.empty() ? std::string() : " (it contains " + found + ")"));
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  if (in) s << in.rdbuf();
  if (!in || in.bad()) throw ConfigError("config: cannot read " + file.string());
  Config c = parse_config_text(s.str(), file.parent_path(),  // empty: relative to the working directory
                               file.stem().string(), file.string());
  c.source_file = file.string();
  return c;
}

}  // namespace cg::config
