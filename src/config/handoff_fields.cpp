#include "src/config/handoff_fields.hpp"
#include "src/core/format.hpp"

#include <vector>

namespace cg::config {
namespace {

// An array of distinct entries of `names`: sets the flag of each entry listed, clears the others.
void read_flags(const Field& d, std::initializer_list<const char*> names, const std::vector<bool*>& flags) {
  const std::size_t n = d.expect_array(1, names.size());
  for (bool* f : flags) *f = false;
  for (std::size_t i = 0; i < n; ++i) {
    bool& on = *flags[static_cast<std::size_t>(d.item(i).choice(names))];
    if (on) fail(d.item(i).path(), "lists " + d.item(i).json().dump() + " twice");
    on = true;
  }
}

}  // namespace

void read_handoff_output_fields(const Field& out, OutputOptions& o) {
  o.stl_deflection = out.number_or("stl_deflection", o.stl_deflection, closed(1e-4, 10), "mm");
  o.stl_angular_deflection_deg = out.number_or("stl_angular_deflection_deg", o.stl_angular_deflection_deg, closed(1, 90), "deg");
  if (out.has("section_spans")) {
    const Field s = out.at("section_spans");
    const std::size_t n = s.expect_array(1, 12);
    o.section_spans.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const double span = s.item(i).number(closed(0, 1));
      if (i > 0 && span <= o.section_spans.back()) {
        const ValueLimitText t = format_value_limit(span, o.section_spans.back(), Allowed::above);
        fail(s.item(i).path(), "section spans must be strictly increasing, got " + t.value + " after " + t.limit);
      }
      o.section_spans.push_back(span);
    }
  }
}

MeshConfig mesh_config(const Field& f) {
  if (!f.is_object()) fail(f.path(), "must be an object, got " + json_type_name(f.json()));
  f.expect_object({"max_size", "min_size", "curvature_elements", "feature_curvature_elements", "size_growth", "domains",
                   "formats", "physical_groups", "threads", "optimize"});
  MeshConfig m;
  m.max_size = f.number_or("max_size", m.max_size, closed(0.01, 1000), "mm");
  m.min_size = f.number_or("min_size", m.min_size, closed(0.001, m.max_size), "mm (<= max_size)");
  m.curvature_elements = f.integer_or("curvature_elements", m.curvature_elements, 0, 200);
  m.feature_curvature_elements = f.integer_or("feature_curvature_elements", m.feature_curvature_elements, 0, 200);
  m.size_growth = f.number_or("size_growth", m.size_growth, positive(2), "mm per mm");
  if (f.has("domains")) read_flags(f.at("domains"), {"metal", "coolant"}, {&m.metal, &m.coolant});
  if (f.has("formats")) read_flags(f.at("formats"), {"msh", "vtu", "cgns"}, {&m.msh, &m.vtu, &m.cgns});
  if (f.has("physical_groups")) m.group_by_face_name = f.at("physical_groups").choice({"kind", "face_name"}) == 1;
  m.threads = f.integer_or("threads", m.threads, 1, 256);
  m.optimize = f.boolean_or("optimize", m.optimize);
  return m;
}

}  // namespace cg::config
