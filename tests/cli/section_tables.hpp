#pragma once
// Section tables of a blade for the round trips of blade.import format "sections" (test code, not the
// product's): the sections of a geomTurbo file (the product's export) written one table per section,
// the outline once around starting mid pressure side; annular rows in metres as x r theta_deg, cascades
// in mm as x, y, z. Returns the config document importing them with the given flow path.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "src/blade_import/geomturbo_reader.hpp"

namespace cg::test {

inline nlohmann::json tables_import(const std::filesystem::path& geomturbo, const std::filesystem::path& dir,
                                    const nlohmann::json& flow_path) {
  const blade_import::ImportedBlade b = blade_import::read_geomturbo(geomturbo.string());
  const bool annular = b.kind == blade_import::RowKind::Annular;
  nlohmann::json files = nlohmann::json::array();
  for (std::size_t k = 0; k < b.sections.size(); ++k) {
    const auto& s = b.sections[k];
    std::vector<Eigen::Vector3d> loop = s.suction;
    for (std::size_t i = s.pressure.size() - 2; i >= 1; --i) loop.push_back(s.pressure[i]);
    std::rotate(loop.begin(), loop.begin() + static_cast<long>(s.suction.size() + s.pressure.size() / 2), loop.end());
    const std::string name = "section_" + std::to_string(k) + ".txt";
    std::ofstream out(dir / name);
    out.precision(12);
    out << (annular ? "x_m r_m theta_deg\n" : "# x y z, mm\n");
    for (const auto& p : loop) {
      if (annular)
        out << p.x() / 1000 << " " << std::hypot(p.y(), p.z()) / 1000 << " " << std::atan2(p.z(), p.y()) * 180 / M_PI << "\n";
      else
        out << p.x() << ", " << p.y() << ", " << p.z() << "\n";
    }
    files.push_back(name);
  }
  nlohmann::json im = {{"format", "sections"}, {"files", files}, {"frame", annular ? "xrtheta" : "xyz"}};
  if (annular) im["unit"] = "m";
  return {{"units", "mm"}, {"flow_path", flow_path}, {"blade", {{"import", im}}}};
}

}  // namespace cg::test
