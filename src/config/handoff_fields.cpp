#include "src/config/handoff_fields.hpp"

namespace cg::config {
namespace {

bool boolean_or(const Field& f, const char* key, bool fallback) {
  if (!f.has(key)) return fallback;
  const Field b = f.at(key);
  if (!b.json().is_boolean()) fail(b.path(), "must be true or false, got " + json_type_name(b.json()));
  return b.json().get<bool>();
}

}  // namespace

HandoffOutputFields handoff_output_fields(const Field& out) {
  HandoffOutputFields h;
  if (out.has("formats")) {
    const Field f = out.at("formats");
    const std::size_t n = f.expect_array(1);
    h.formats.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const Field item = f.item(i);
      try {
        if (!h.formats.insert(io::parse_output_format(item.string())).second) fail(item.path(), "listed twice");
      } catch (const InvalidGeometry& e) {
        fail(item.path(), e.what());
      }
    }
  }
  h.stl_deflection = out.number_or("stl_deflection", h.stl_deflection, closed(1e-4, 10), "mm");
  h.stl_angular_deflection_deg =
      out.number_or("stl_angular_deflection_deg", h.stl_angular_deflection_deg, closed(1, 90), "deg");
  if (out.has("section_spans")) {
    const Field s = out.at("section_spans");
    const std::size_t n = s.expect_array(1, 12);
    h.section_spans.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const double span = s.item(i).number(closed(0, 1));
      if (i > 0 && span <= h.section_spans.back())
        fail(s.item(i).path(), "section spans must be strictly increasing, got " + std::to_string(span) + " after " +
                                   std::to_string(h.section_spans.back()));
      h.section_spans.push_back(span);
    }
  }
  return h;
}

mesh::MeshOptions mesh_options(const Field& f) {
  if (!f.is_object()) fail(f.path(), "must be an object, got " + json_type_name(f.json()));
  f.expect_object({"max_size", "min_size", "curvature_elements", "feature_curvature_elements", "domains", "formats",
                   "physical_groups", "threads", "optimize"});
  mesh::MeshOptions m;
  m.max_size = f.number_or("max_size", m.max_size, closed(0.01, 1000), "mm");
  m.min_size = f.number_or("min_size", m.min_size, closed(0.001, m.max_size), "mm (<= max_size)");
  m.curvature_elements = f.integer_or("curvature_elements", m.curvature_elements, 0, 200);
  m.feature_curvature_elements = f.integer_or("feature_curvature_elements", m.feature_curvature_elements, 0, 200);
  if (f.has("domains")) {
    const Field d = f.at("domains");
    const std::size_t n = d.expect_array(1, 2);
    m.metal = m.coolant = false;
    for (std::size_t i = 0; i < n; ++i) (d.item(i).choice({"metal", "coolant"}) == 0 ? m.metal : m.coolant) = true;
  }
  if (f.has("formats")) {
    const Field d = f.at("formats");
    const std::size_t n = d.expect_array(1, 2);
    m.write_msh = m.write_vtu = false;
    for (std::size_t i = 0; i < n; ++i) (d.item(i).choice({"msh", "vtu"}) == 0 ? m.write_msh : m.write_vtu) = true;
  }
  if (f.has("physical_groups"))
    m.groups = f.at("physical_groups").choice({"kind", "face_name"}) == 0 ? mesh::GroupBy::Kind : mesh::GroupBy::FaceName;
  m.threads = f.integer_or("threads", m.threads, 1, 256);
  m.optimize = boolean_or(f, "optimize", m.optimize);
  return m;
}

}  // namespace cg::config
