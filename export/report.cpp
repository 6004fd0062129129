#include "export/report.hpp"

#include <fstream>

#include "export/atomic_file.hpp"

namespace cg::io {

nlohmann::ordered_json report_json(const ReportContent& c) {
  using json = nlohmann::ordered_json;
  const brep::SolidCheck& k = c.check;
  json checks = json::object();
  for (const brep::Check* x : k.checks()) checks[x->name] = {{"passed", x->passed}, {"message", x->message}};
  json size = json::array();
  for (int i = 0; i < 3; ++i) size.push_back(k.bbox_max[static_cast<std::size_t>(i)] - k.bbox_min[static_cast<std::size_t>(i)]);
  json out{
      {"generator", "coolinggen"},
      {"version", c.version},
      {"input_hash", c.input_hash},
      {"valid", k.all_passed()},
      {"units", {{"length", "mm"}, {"area", "mm^2"}, {"volume", "mm^3"}, {"angle", "deg"}, {"time", "s"}}},
      {"model", c.model},
      {"solid",
       {{"volume_mm3", k.volume},
        {"volume_error_mm3", k.volume_error},
        {"surface_area_mm2", k.area()},
        {"bbox_mm", {{"min", k.bbox_min}, {"max", k.bbox_max}, {"size", size}}},
        {"face_count", k.face_count},
        {"solid_count", k.solid_count},
        {"faces", c.face_names},
        {"mesh_triangles", k.mesh_triangles}}},
      {"checks", checks},
      {"warnings", c.warnings},
      {"timings_s", c.timings_s},
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
