#include "src/network/network_sections.hpp"

#include <algorithm>

#include "features/passages/span_sections.hpp"

namespace cg::network {

std::map<std::string, std::vector<features::CrossSection>> measure_stations(const blade::BladeModel& model,
                                                                           const brep::Part& part,
                                                                           std::vector<double> spans) {
  std::sort(spans.begin(), spans.end());
  spans.erase(std::unique(spans.begin(), spans.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
              spans.end());
  std::map<std::string, std::vector<features::CrossSection>> out;
  if (spans.empty() || part.empty()) return out;
  for (const features::SpanSection& cut : features::span_sections(part, features::span_surfaces(model, spans)))
    for (const features::SectionPassage& p : cut.passages)
      if (p.area > 0) out[p.name].push_back({cut.span, p.area, p.wetted_perimeter, p.hydraulic_diameter});
  for (auto& [name, secs] : out)
    std::sort(secs.begin(), secs.end(), [](const auto& a, const auto& b) { return a.span < b.span; });
  return out;
}

}  // namespace cg::network
