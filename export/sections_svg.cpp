#include "export/sections_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "export/atomic_file.hpp"
#include "export/feature_style.hpp"
#include "export/xml_text.hpp"

namespace cg::io {
namespace {

constexpr double kMargin = 30, kHeader = 70, kTableLine = 16;

std::string fmt(double v, int digits = 2) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

struct Box {
  Eigen::Vector2d lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
  void add(const Eigen::Vector2d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Eigen::Vector2d size() const { return hi - lo; }
};

Box box_of(const features::SpanSection& c) {
  Box b;
  for (const auto& curve : c.curves)
    for (const auto& p : curve.points) b.add(p);
  return b;
}

// A "nice" scale bar length (1, 2, 5 x 10^k mm) of about a fifth of the drawing width.
double scale_bar_mm(double width_mm) {
  const double target = width_mm / 5, e = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * e <= target) return m * e;
  return e;
}

}  // namespace

std::string sections_svg(const std::vector<features::SpanSection>& cuts, const std::string& title) {
  std::vector<Box> boxes;
  double max_w = 1e-9, max_h = 1e-9;
  int max_passages = 0;
  for (const auto& c : cuts) {
    boxes.push_back(box_of(c));
    if (c.curves.empty()) continue;
    max_w = std::max(max_w, boxes.back().size().x());
    max_h = std::max(max_h, boxes.back().size().y());
    max_passages = std::max(max_passages, static_cast<int>(c.passages.size()));
  }
  // Wide sections (a rotor blade seen blade-to-blade) in two wide panels per row, tall ones (a vane with
  // a large stagger) in three tall panels per row, so the drawing fills its panel either way.
  const bool tall = max_h > max_w;
  const double kPanelW = tall ? 420 : 560, kPanelH = tall ? 600 : 420;
  const double table_h = max_passages > 0 ? kTableLine * (max_passages + 2) : 10;
  const double plot_h = kPanelH - kHeader - table_h - 24;  // 24 px for the scale bar
  const double scale = std::min((kPanelW - 2 * kMargin) / max_w, (plot_h - 10) / max_h);  // px per mm
  const int columns = static_cast<int>(std::min<std::size_t>(cuts.size(), tall ? 3 : 2));
  const int rows = static_cast<int>((cuts.size() + columns - 1) / columns);
  const double legend_h = 60;
  const double width = columns * kPanelW, height = legend_h + rows * kPanelH;

  std::set<std::string> kinds;
  for (const auto& c : cuts)
    for (const auto& curve : c.curves) kinds.insert(brep::feature_kind(curve.name));

  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width, 0) << "\" height=\"" << fmt(height, 0)
    << "\" viewBox=\"0 0 " << fmt(width, 0) << " " << fmt(height, 0) << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
    << "<text x=\"16\" y=\"26\" font-size=\"18\" font-weight=\"bold\">" << xml_escape(title) << " — sections (mm), scale "
    << fmt(scale, 2) << " px/mm</text>\n";
  double lx = 16;
  for (const auto& k : kinds) {
    s << "<rect x=\"" << fmt(lx) << "\" y=\"38\" width=\"14\" height=\"14\" fill=\"" << hex_colour(kind_colour(k))
      << "\"/><text x=\"" << fmt(lx + 18) << "\" y=\"50\" font-size=\"13\">" << k << "</text>\n";
    lx += 30 + 8.0 * k.size();
  }

  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const features::SpanSection& c = cuts[i];
    const double ox = (i % columns) * kPanelW, oy = legend_h + (i / columns) * kPanelH;
    s << "<g>\n<rect x=\"" << fmt(ox + 4) << "\" y=\"" << fmt(oy + 4) << "\" width=\"" << fmt(kPanelW - 8) << "\" height=\""
      << fmt(kPanelH - 8) << "\" fill=\"none\" stroke=\"#c8c8c8\"/>\n";
    s << "<text x=\"" << fmt(ox + 16) << "\" y=\"" << fmt(oy + 26) << "\" font-size=\"15\" font-weight=\"bold\">span "
      << fmt(c.span, 2) << "</text>\n";
    double hole_area = 0;
    for (const auto& h : c.holes) hole_area += h.area;
    s << "<text x=\"" << fmt(ox + 16) << "\" y=\"" << fmt(oy + 46) << "\" font-size=\"12\">chord " << fmt(c.chord)
      << " mm, metal " << fmt(c.metal_area) << " mm², " << c.passages.size() << " passage(s), " << c.holes.size()
      << " hole(s) " << fmt(hole_area) << " mm²</text>\n";
    if (c.curves.empty()) {
      s << "<text x=\"" << fmt(ox + 16) << "\" y=\"" << fmt(oy + 90) << "\" font-size=\"13\">no section</text>\n</g>\n";
      continue;
    }
    const Box& b = boxes[i];
    // Centre the drawing in the plot area; SVG y grows downwards.
    const Eigen::Vector2d mid = 0.5 * (b.lo + b.hi);
    const double cx = ox + kPanelW / 2, cy = oy + kHeader + plot_h / 2;
    auto X = [&](const Eigen::Vector2d& p) { return cx + (p.x() - mid.x()) * scale; };
    auto Y = [&](const Eigen::Vector2d& p) { return cy - (p.y() - mid.y()) * scale; };
    auto path = [&](const std::vector<Eigen::Vector2d>& pts, bool close) {
      std::ostringstream d;
      for (std::size_t k = 0; k < pts.size(); ++k) d << (k ? " L" : "M") << fmt(X(pts[k])) << "," << fmt(Y(pts[k]));
      if (close) d << " Z";
      return d.str();
    };
    // Metal: per body, all loops in one even-odd path (cavities cut out).
    std::set<int> bodies;
    for (const auto& l : c.loops) bodies.insert(l.body);
    for (int body : bodies) {
      s << "<path fill-rule=\"evenodd\" fill=\"" << (body == 0 ? "#d5d9e0" : "#cde8d2") << "\" d=\"";
      for (const auto& l : c.loops)
        if (l.body == body) s << path(l.points, true) << " ";
      s << "\"/>\n";
    }
    for (const auto& curve : c.curves)
      s << "<path fill=\"none\" stroke-width=\"1.6\" stroke-linejoin=\"round\" stroke=\""
        << hex_colour(kind_colour(brep::feature_kind(curve.name))) << "\" d=\"" << path(curve.points, false) << "\"/>\n";
    // Chord dimension line.
    s << "<line x1=\"" << fmt(X(c.chord_a)) << "\" y1=\"" << fmt(Y(c.chord_a)) << "\" x2=\"" << fmt(X(c.chord_b)) << "\" y2=\""
      << fmt(Y(c.chord_b)) << "\" stroke=\"#333333\" stroke-width=\"0.8\" stroke-dasharray=\"5,3\"/>\n";
    for (const auto* p : {&c.chord_a, &c.chord_b})
      s << "<circle cx=\"" << fmt(X(*p)) << "\" cy=\"" << fmt(Y(*p)) << "\" r=\"2.5\" fill=\"#333333\"/>\n";
    const Eigen::Vector2d cm = 0.5 * (c.chord_a + c.chord_b);
    s << "<text x=\"" << fmt(X(cm)) << "\" y=\"" << fmt(Y(cm) - 6) << "\" font-size=\"11\" text-anchor=\"middle\" fill=\"#333333\">"
      << fmt(c.chord) << "</text>\n";
    // Passages: number at the centroid, table below.
    double ty = oy + kPanelH - table_h + 4;
    // Table columns at fixed offsets (SVG text has no tab stops).
    const double col[4] = {16, 90, 190, 280};
    auto row = [&](double y, const std::string (&cells)[4], bool bold) {
      for (int k = 0; k < 4; ++k)
        s << "<text x=\"" << fmt(ox + col[k]) << "\" y=\"" << fmt(y) << "\" font-size=\"12\""
          << (bold ? " font-weight=\"bold\"" : "") << ">" << cells[k] << "</text>\n";
    };
    if (!c.passages.empty()) row(ty, {"#", "area mm²", "D_h mm", "passage"}, true);
    for (std::size_t k = 0; k < c.passages.size(); ++k) {
      const features::SectionPassage& p = c.passages[k];
      s << "<text x=\"" << fmt(X(p.centroid)) << "\" y=\"" << fmt(Y(p.centroid) + 4) << "\" font-size=\"11\" text-anchor=\"middle\" "
        << "font-weight=\"bold\">" << k + 1 << "</text>\n";
      ty += kTableLine;
      row(ty, {std::to_string(k + 1), fmt(p.area), fmt(p.hydraulic_diameter), xml_escape(p.name)}, false);
    }
    // Scale bar.
    const double bar = scale_bar_mm(b.size().x());
    const double bx = ox + kPanelW - kMargin - bar * scale, by = oy + kPanelH - 14;  // bottom right
    s << "<line x1=\"" << fmt(bx) << "\" y1=\"" << fmt(by) << "\" x2=\"" << fmt(bx + bar * scale) << "\" y2=\"" << fmt(by)
      << "\" stroke=\"#000000\" stroke-width=\"2\"/><text x=\"" << fmt(bx + bar * scale / 2) << "\" y=\"" << fmt(by - 5)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << fmt(bar, bar < 1 ? 1 : 0) << " mm</text>\n";
    s << "</g>\n";
  }
  s << "</svg>\n";
  return s.str();
}

void write_sections_svg(const std::filesystem::path& file, const std::vector<features::SpanSection>& cuts, const std::string& title) {
  const std::string text = sections_svg(cuts, title);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

}  // namespace cg::io
