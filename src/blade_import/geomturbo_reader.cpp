#include "src/blade_import/geomturbo_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade_import {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

struct Line {
  int no = 0;
  std::vector<std::string> tok;
  std::string key() const { return upper(tok.front()); }
};

struct Side {
  std::vector<std::vector<Eigen::Vector3d>> sections;  // in file coordinates
  std::vector<std::vector<int>> lines;
  std::vector<bool> zrth;
  std::vector<int> start;
};

class Reader {
 public:
  Reader(std::istream& in, std::string name) : name_(std::move(name)) {
    std::string text;
    int no = 0;
    while (std::getline(in, text)) {
      ++no;
      std::istringstream ss(text);
      Line l;
      l.no = no;
      std::string t;
      while (ss >> t) l.tok.push_back(t);
      if (l.tok.empty() || l.tok.front()[0] == '#') continue;
      lines_.push_back(std::move(l));
    }
  }

  ImportedBlade read();

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InvalidGeometry(name_ + ":" + std::to_string(line) + ": " + what);
  }
  const Line& next(const char* expected) {
    if (pos_ >= lines_.size())
      fail(lines_.empty() ? 1 : lines_.back().no, std::string("the file ends where ") + expected + " was expected");
    return lines_[pos_++];
  }
  double number(const Line& l, std::size_t i, const char* what) const {
    if (i >= l.tok.size()) fail(l.no, std::string("expected ") + what);
    const char* s = l.tok[i].c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v))
      fail(l.no, std::string("expected ") + what + ", got \"" + l.tok[i] + "\"");
    return v;
  }
  int count(const Line& l, const char* what) const {
    const double v = number(l, 0, what);
    if (v != std::floor(v) || v < 1 || v > 1e6 || l.tok.size() != 1)
      fail(l.no, std::string("expected ") + what + " (one whole number >= 1)");
    return static_cast<int>(v);
  }
  void basic_curve(const Line& begin);
  void channel_curve(const Line& begin);
  void blade_geometry(const Line& begin);
  void side(Side& s, const char* which);
  void tip_gap();
  std::vector<Eigen::Vector2d> channel(const char* which, int& line) const;

  std::string name_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  double unit_mm_ = 1, units_factor_ = 1, blade_units_ = 1;
  bool cascade_ = false;
  std::map<std::string, std::vector<Eigen::Vector2d>> curves_;
  std::map<std::string, int> curve_lines_;
  std::map<std::string, std::vector<std::string>> channel_curves_;  // "HUB"/"SHROUD" -> basic curve names
  Side suction_, pressure_;
  int blades_ = 0, periodicity_ = 0, blade_line_ = 0;
  double gap_le_ = 0, gap_te_ = 0;
};

void Reader::basic_curve(const Line& begin) {
  std::string name;
  while (true) {
    const Line& l = next("NI_END basic_curve");
    if (l.key() == "NAME" && l.tok.size() >= 2) name = l.tok[1];
    else if (l.key() == "NI_BEGIN" && l.tok.size() >= 2 && upper(l.tok[1]) == "ZRCURVE") {
      const Line& zr = next("ZR");
      if (zr.key() != "ZR") fail(zr.no, "expected ZR after NI_BEGIN zrcurve, got \"" + zr.tok[0] + "\"");
      const int n = count(next("the number of points"), "the number of zrcurve points");
      std::vector<Eigen::Vector2d>& pts = curves_[name];
      curve_lines_[name] = begin.no;
      for (int i = 0; i < n; ++i) {
        const Line& p = next("a zrcurve point");
        if (p.tok.size() != 2) fail(p.no, "expected 2 numbers (z r) of zrcurve " + name + "'s point " + std::to_string(i + 1) + " of " + std::to_string(n));
        pts.emplace_back(number(p, 0, "z"), number(p, 1, "r"));
      }
    } else if (l.key() == "NI_BEGIN") {
      fail(l.no, "basic_curve " + name + ": only zrcurve point lists are read, got " + l.tok.back());
    } else if (l.key() == "NI_END") {
      return;
    }
  }
}

void Reader::channel_curve(const Line& begin) {
  const std::string which = begin.tok.size() >= 3 ? upper(begin.tok[2]) : "";
  while (true) {
    const Line& l = next("NI_END channel_curve");
    if (l.key() == "NI_END") return;
    if (l.key() == "VERTEX" && l.tok.size() >= 3 && upper(l.tok[1]) == "CURVE_P") {
      auto& names = channel_curves_[which];
      if (names.empty() || names.back() != l.tok[2]) names.push_back(l.tok[2]);
    }
  }
}

void Reader::side(Side& s, const char* which) {
  const Line& kind = next("SECTIONAL");
  if (kind.key() != "SECTIONAL")
    fail(kind.no, std::string(which) + " side: only SECTIONAL blades are read, got \"" + kind.tok[0] + "\"");
  const int n = count(next("the number of sections"), "the number of sections");
  for (int k = 0; k < n; ++k) {
    const Line& f = next("XYZ or ZRTH");
    const std::string fk = f.key();
    if (fk != "XYZ" && fk != "ZRTH")
      fail(f.no, std::string(which) + " section " + std::to_string(k + 1) + ": expected XYZ or ZRTH, got \"" + f.tok[0] + "\"");
    const int m = count(next("the number of points"), "the number of section points");
    s.zrth.push_back(fk == "ZRTH");
    s.start.push_back(f.no);
    s.sections.emplace_back();
    s.lines.emplace_back();
    for (int i = 0; i < m; ++i) {
      const Line& p = next("a section point");
      if (p.tok.size() != 3)
        fail(p.no, std::string(which) + " section " + std::to_string(k + 1) + ": expected 3 numbers (" +
                       (fk == "XYZ" ? "x y z" : "z r th") + ") for point " + std::to_string(i + 1) + " of " +
                       std::to_string(m) + ", got " + std::to_string(p.tok.size()) + " fields");
      s.sections.back().emplace_back(number(p, 0, "a number"), number(p, 1, "a number"), number(p, 2, "a number"));
      s.lines.back().push_back(p.no);
    }
  }
}

void Reader::blade_geometry(const Line& begin) {
  if (blade_line_ != 0)
    fail(begin.no, "a second nibladegeometry (the first at line " + std::to_string(blade_line_) +
                       "): one blade is imported; write the blade to import into a file of its own");
  blade_line_ = begin.no;
  while (true) {
    const Line& l = next("NI_END nibladegeometry");
    const std::string k = l.key();
    if (k == "NI_END") return;
    if (k == "NUMBER_OF_BLADES") blades_ = count(Line{l.no, {l.tok.size() > 1 ? l.tok[1] : ""}}, "number_of_blades");
    else if (k == "UNITS") {
      blade_units_ = number(l, 1, "the units factor");
      if (!(blade_units_ > 0)) fail(l.no, "units must be > 0");
    } else if (k == "SUCTION") side(suction_, "suction");
    else if (k == "PRESSURE") side(pressure_, "pressure");
  }
}

void Reader::tip_gap() {
  while (true) {
    const Line& l = next("NI_END NITipGap");
    const std::string k = l.key();
    if (k == "NI_END") return;
    if (k == "WIDTH_AT_LEADING_EDGE") gap_le_ = number(l, 1, "the tip gap width");
    if (k == "WIDTH_AT_TRAILING_EDGE") gap_te_ = number(l, 1, "the tip gap width");
    if (gap_le_ < 0 || gap_te_ < 0) fail(l.no, "the tip gap width must be >= 0");
  }
}

std::vector<Eigen::Vector2d> Reader::channel(const char* which, int& line) const {
  std::vector<std::string> names;
  const auto cc = channel_curves_.find(upper(which));
  if (cc != channel_curves_.end()) names = cc->second;
  else
    for (const auto& [n, pts] : curves_)
      if (upper(n).find(upper(which)) != std::string::npos) names.push_back(n);
  if (names.empty()) fail(lines_.empty() ? 1 : lines_.front().no, std::string("no ") + which + " curve in the CHANNEL");
  std::vector<Eigen::Vector2d> out;
  for (const std::string& n : names) {
    const auto c = curves_.find(n);
    if (c == curves_.end()) fail(lines_.front().no, std::string("the channel's ") + which + " names basic_curve " + n + ", which is not given");
    line = curve_lines_.at(n);
    for (const Eigen::Vector2d& p : c->second)
      if (out.empty() || (p - out.back()).norm() > 0) out.push_back(p);
  }
  return out;
}

ImportedBlade Reader::read() {
  if (lines_.empty() || lines_[0].tok.size() < 2 || upper(lines_[0].tok[0]) != "GEOMETRY" || upper(lines_[0].tok[1]) != "TURBO")
    fail(lines_.empty() ? 1 : lines_[0].no, "not a geomTurbo file (it must start with GEOMETRY TURBO)");
  pos_ = 1;
  while (pos_ < lines_.size()) {
    const Line& l = lines_[pos_++];
    const std::string k = l.key();
    const std::string what = l.tok.size() > 1 ? upper(l.tok[1]) : "";
    if (k == "UNITS" && blade_line_ == 0) {
      static const std::map<std::string, double> units{{"METERS", 1000}, {"METRES", 1000}, {"MILLIMETERS", 1},
                                                       {"MILLIMETRES", 1}, {"CENTIMETERS", 10}, {"CENTIMETRES", 10},
                                                       {"INCHES", 25.4}};
      const auto u = units.find(what);
      if (u == units.end()) fail(l.no, "UNITS must be Meters, Millimeters, Centimeters or Inches, got \"" + (l.tok.size() > 1 ? l.tok[1] : "") + "\"");
      unit_mm_ = u->second;
    } else if (k == "UNITS-FACTOR") {
      units_factor_ = number(l, 1, "the units factor");
      if (!(units_factor_ > 0)) fail(l.no, "UNITS-FACTOR must be > 0");
    } else if (k == "CASCADE") {
      if (what != "YES" && what != "NO") fail(l.no, "cascade must be yes or no");
      cascade_ = what == "YES";
    } else if (k == "PERIODICITY") {
      periodicity_ = count(Line{l.no, {l.tok.size() > 1 ? l.tok[1] : ""}}, "PERIODICITY");
    } else if (k == "NI_BEGIN") {
      if (what == "BASIC_CURVE") basic_curve(l);
      else if (what == "CHANNEL_CURVE") channel_curve(l);
      else if (what == "NIBLADEGEOMETRY") blade_geometry(l);
      else if (what == "NITIPGAP") tip_gap();
    }
  }
  if (blade_line_ == 0) fail(lines_.back().no, "no nibladegeometry block (the blade's sections)");
  if (suction_.sections.empty() || pressure_.sections.empty())
    fail(blade_line_, "the blade needs both a suction and a pressure side");
  if (suction_.sections.size() != pressure_.sections.size())
    fail(pressure_.start.front(), "the suction side has " + std::to_string(suction_.sections.size()) +
                                      " sections, the pressure side " + std::to_string(pressure_.sections.size()));
  ImportedBlade b;
  b.file = name_;
  b.kind = cascade_ ? RowKind::Cascade : RowKind::Annular;
  b.number_of_blades = blades_ > 0 ? blades_ : periodicity_;
  const double mm = unit_mm_ * units_factor_;
  b.hub = channel("hub", b.hub_line);
  b.casing = channel("shroud", b.casing_line);
  b.tip_gap_le = gap_le_ * mm;
  b.tip_gap_te = gap_te_ * mm;
  double r_hub = 0;
  if (cascade_) {
    r_hub = b.hub.front().y();
    for (const auto* c : {&b.hub, &b.casing})
      for (const Eigen::Vector2d& p : *c)
        if (std::abs(p.y() - c->front().y()) > 1e-9 * (1 + std::abs(p.y())))
          fail(c == &b.hub ? b.hub_line : b.casing_line, "a cascade's hub and shroud must be lines of constant r");
  }
  for (auto* c : {&b.hub, &b.casing})
    for (Eigen::Vector2d& p : *c) p = mm * Eigen::Vector2d(p.x(), p.y() - r_hub);
  const double bm = mm * blade_units_;
  auto convert = [&](const Eigen::Vector3d& p, bool zrth, int line) -> Eigen::Vector3d {
    if (cascade_) {
      if (zrth) fail(line, "a cascade's sections must be XYZ");
      return Eigen::Vector3d(bm * p.z(), bm * p.y(), bm * p.x() - mm * r_hub);
    }
    if (zrth) return Eigen::Vector3d(bm * p.x(), bm * p.y() * std::cos(p.z()), bm * p.y() * std::sin(p.z()));
    return bm * Eigen::Vector3d(p.z(), p.x(), p.y());
  };
  for (std::size_t k = 0; k < suction_.sections.size(); ++k) {
    ImportedSection s;
    s.line = suction_.start[k];
    s.suction_lines = suction_.lines[k];
    s.pressure_lines = pressure_.lines[k];
    for (std::size_t i = 0; i < suction_.sections[k].size(); ++i)
      s.suction.push_back(convert(suction_.sections[k][i], suction_.zrth[k], s.suction_lines[i]));
    for (std::size_t i = 0; i < pressure_.sections[k].size(); ++i)
      s.pressure.push_back(convert(pressure_.sections[k][i], pressure_.zrth[k], s.pressure_lines[i]));
    b.sections.push_back(std::move(s));
  }
  return b;
}

}  // namespace

ImportedBlade parse_geomturbo(std::istream& in, const std::string& name) { return Reader(in, name).read(); }

ImportedBlade read_geomturbo(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidGeometry(path + ": cannot be read");
  return parse_geomturbo(in, path);
}

}  // namespace cg::blade_import
