#include "export/report.hpp"

#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "export/atomic_file.hpp"

namespace cg::io {

using json = nlohmann::ordered_json;

json solid_json(const brep::SolidCheck& k, const std::map<std::string, int>& faces) {
  json size = json::array();
  for (int i = 0; i < 3; ++i) size.push_back(k.bbox_max[static_cast<std::size_t>(i)] - k.bbox_min[static_cast<std::size_t>(i)]);
  return {{"volume_mm3", k.volume},
          {"volume_error_mm3", k.volume_error},
          {"surface_area_mm2", k.area()},
          {"bbox_mm", {{"min", k.bbox_min}, {"max", k.bbox_max}, {"size", size}}},
          {"face_count", k.face_count},
          {"solid_count", k.solid_count},
          {"faces", faces},
          {"mesh_triangles", k.mesh_triangles}};
}

json checks_json(const brep::SolidCheck& k) {
  json checks = json::object();
  for (const brep::Check* x : k.checks()) checks[x->name] = {{"passed", x->passed}, {"message", x->message}};
  return checks;
}

namespace {
double number(const json& j) { return j.is_null() ? std::numeric_limits<double>::quiet_NaN() : j.get<double>(); }
}  // namespace

brep::SolidCheck solid_check_of(const json& solid, const json& checks) {
  brep::SolidCheck k;
  brep::Check* members[] = {&k.one_solid, &k.brep_valid, &k.no_free_edges, &k.oriented_shells, &k.closed_mesh, &k.positive_volume};
  if (checks.size() != std::size(members)) throw std::runtime_error("a solid check has " + std::to_string(std::size(members)) + " checks");
  std::size_t i = 0;
  for (const auto& [name, c] : checks.items()) *members[i++] = {name, c.at("passed").get<bool>(), c.at("message").get<std::string>(), 0.0};
  k.volume = number(solid.at("volume_mm3"));
  k.volume_error = number(solid.at("volume_error_mm3"));
  k.area_ = number(solid.at("surface_area_mm2"));
  for (std::size_t a = 0; a < 3; ++a) {
    k.bbox_min[a] = number(solid.at("bbox_mm").at("min").at(a));
    k.bbox_max[a] = number(solid.at("bbox_mm").at("max").at(a));
  }
  k.face_count = solid.at("face_count").get<int>();
  k.solid_count = solid.at("solid_count").get<int>();
  k.mesh_triangles = solid.at("mesh_triangles").get<int>();
  return k;
}

json report_json(const ReportContent& c) {
  const brep::SolidCheck& k = c.check;
  json out{
      {"generator", "coolinggen"},
      {"version", c.version},
      {"input_hash", c.input_hash},
      {"valid", k.all_passed()},
      {"units", {{"length", "mm"}, {"area", "mm^2"}, {"volume", "mm^3"}, {"angle", "deg"}, {"time", "s"}}},
      {"model", c.model},
      {"solid", solid_json(k, c.face_names)},
      {"checks", checks_json(k)},
      {"warnings", c.warnings},
      {"timings_s", c.timings_s},
      {"threads", c.threads},
      {"outputs", c.outputs},
  };
  for (const auto& [key, value] : c.extra.items()) out[key] = value;
  return out;
}

void write_report(const std::filesystem::path& file, const ReportContent& content) {
  const std::string text = report_json(content).dump(2) + "\n";
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

}  // namespace cg::io
