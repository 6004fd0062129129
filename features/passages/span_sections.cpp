#include "features/passages/span_sections.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "features/passages/section_trace.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/core/parallel.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// "chamber_2" before "chamber_10": digit runs compare as numbers.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je]))) ++je;
      const std::string na = a.substr(i, ie - i), nb = b.substr(j, je - j);
      if (na.size() != nb.size()) return na.size() < nb.size();
      if (na != nb) return na < nb;
      i = ie, j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

bool inside(const std::vector<Vec2>& poly, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) in = !in;
  }
  return in;
}

Vec2 centroid(const std::vector<Vec2>& poly) {
  Vec2 c = Vec2::Zero();
  double a = 0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    const double w = p.x() * q.y() - q.x() * p.y();
    a += w;
    c += w * (p + q);
  }
  return std::abs(a) > 0 ? Vec2(c / (3 * a)) : poly.front();
}

// The two farthest points of a polygon: on its convex hull (monotone chain), pairwise there.
std::pair<Vec2, Vec2> diameter(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) { return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x(); };
  std::vector<Vec2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Vec2& p : pts) {
      while (hull.size() >= base + 2 && turn(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(pts.begin(), pts.end());
  }
  std::pair<Vec2, Vec2> best{pts.front(), pts.front()};
  double d = -1;
  for (std::size_t i = 0; i < hull.size(); ++i)
    for (std::size_t j = i + 1; j < hull.size(); ++j)
      if ((hull[i] - hull[j]).squaredNorm() > d) {
        d = (hull[i] - hull[j]).squaredNorm();
        best = {hull[i], hull[j]};
      }
  return best;
}

struct Step {
  int piece = 0;
  bool forward = true;
};

struct Loop {
  std::vector<Step> steps;
  std::vector<Vec2> polygon;
  double area = 0, length = 0;
  int depth = 0;
  SectionLoopKind kind = SectionLoopKind::Outer;
  std::string name;
};

// One body's section: its pieces (traced and bridges) and how the loops are closed over openings.
class BodySection {
 public:
  BodySection(const SectionBody& body, SpanSurfaceEvaluator& s, FaceClassifiers& cls)
      : body_(body), s_(s), trace_(trace_section(body, s, cls)) {
    for (std::size_t v = 0; v < trace_.vertices.size(); ++v)
      vertex_of_[{trace_.vertices[v].crossing, trace_.vertices[v].face}] = static_cast<int>(v);
  }

  const SectionTrace& trace() const { return trace_; }
  const std::string& face_name(int piece) const {
    return body_.shape->faces[static_cast<std::size_t>(trace_.pieces[static_cast<std::size_t>(piece)].face)].name;
  }
  bool opening(int piece) const { return !trace_.pieces[static_cast<std::size_t>(piece)].bridge && is_opening_face(face_name(piece)); }

  /// Sealed loops and hole loops (see the header), with `unclosed` the openings left joined.
  void loops(std::vector<Loop>& sealed, std::vector<Loop>& holes, int& unclosed) {
    std::vector<int> all(trace_.pieces.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    std::vector<Loop> as_cut = chain(all);
    int left = 0;
    const std::set<std::string> closed = close_openings(as_cut, left);
    std::vector<int> wall, hole;
    for (std::size_t i = 0; i < trace_.pieces.size(); ++i) {
      const int p = static_cast<int>(i);
      const bool in_hole = trace_.pieces[i].bridge || (opening(p) && closed.count(face_name(p)));
      if (trace_.pieces[i].bridge || !in_hole) wall.push_back(p);
      if (in_hole) hole.push_back(p);
    }
    try {
      sealed = chain(wall);
      holes = chain(hole);
      unclosed += left;
    } catch (const FeatureFailure&) {
      // Bridges that do not join up (openings meeting each other on a wall): the loops as cut, every
      // opening left open.
      sealed.clear();
      holes.clear();
      for (Loop& l : as_cut) {
        const bool hole_only = std::all_of(l.steps.begin(), l.steps.end(), [&](const Step& st) { return opening(st.piece); });
        (hole_only ? holes : sealed).push_back(std::move(l));
      }
      unclosed += left + static_cast<int>(closed.size());
    }
    for (Loop& l : holes)
      for (const Step& st : l.steps)
        if (!trace_.pieces[static_cast<std::size_t>(st.piece)].bridge) l.name = face_name(st.piece);
    for (Loop& l : sealed) measure(l);
    for (Loop& l : holes) measure(l);
  }

 private:
  // Pieces `use` into closed loops through their crossings.
  std::vector<Loop> chain(const std::vector<int>& use) const {
    std::map<int, std::vector<std::pair<int, bool>>> at;  // crossing -> (piece, it starts there)
    for (int i : use) {
      const SectionPiece& p = trace_.pieces[static_cast<std::size_t>(i)];
      if (p.first < 0) continue;
      at[p.first].push_back({i, true});
      at[p.last].push_back({i, false});
    }
    std::vector<char> used(trace_.pieces.size(), 0);
    std::vector<Loop> loops;
    for (int i : use) {
      if (used[static_cast<std::size_t>(i)]) continue;
      used[static_cast<std::size_t>(i)] = 1;
      Loop l;
      l.steps.push_back({i, true});
      const SectionPiece& p = trace_.pieces[static_cast<std::size_t>(i)];
      for (int cur = p.last; p.first >= 0 && cur != p.first;) {
        int next = -1;
        bool forward = true;
        for (const auto& [j, starts] : at[cur])
          if (!used[static_cast<std::size_t>(j)]) {
            next = j;
            forward = starts;
            break;
          }
        if (next < 0) {
          const Vec3 q = trace_.crossings[static_cast<std::size_t>(cur)].point;
          throw FeatureFailure("section at span " + format_number(s_.surface().span) + ": a section loop does not close at (" +
                               format_number(q.x()) + ", " + format_number(q.y()) + ", " + format_number(q.z()) +
                               ") after face " + face_name(l.steps.back().piece));
        }
        used[static_cast<std::size_t>(next)] = 1;
        l.steps.push_back({next, forward});
        const SectionPiece& n = trace_.pieces[static_cast<std::size_t>(next)];
        cur = forward ? n.last : n.first;
      }
      loops.push_back(std::move(l));
    }
    return loops;
  }

  // Each run of a loop along one opening's faces ends on a wall at both ends; per opening, the ends on
  // one wall surface are joined by a bridge when there are exactly two. Returns the openings closed.
  std::set<std::string> close_openings(const std::vector<Loop>& loops, int& unclosed) {
    struct End {
      int crossing, wall_face;
    };
    std::map<std::string, std::vector<End>> ends;
    std::set<std::string> names, failed;
    for (std::size_t i = 0; i < trace_.pieces.size(); ++i)
      if (opening(static_cast<int>(i))) names.insert(face_name(static_cast<int>(i)));
    for (const Loop& l : loops) {
      const std::size_t n = l.steps.size();
      std::size_t k0 = 0;
      while (k0 < n && opening(l.steps[k0].piece)) ++k0;
      if (k0 == n) continue;  // a hole's own closed loop, or no opening at all
      for (std::size_t m = 1; m <= n; ++m) {
        const Step& st = l.steps[(k0 + m) % n];
        const Step& before = l.steps[(k0 + m - 1) % n];
        if (!opening(st.piece) || opening(before.piece)) continue;
        const std::string name = face_name(st.piece);
        std::size_t e = m;
        while (opening(l.steps[(k0 + e + 1) % n].piece)) {
          if (face_name(l.steps[(k0 + e + 1) % n].piece) != name) failed.insert(name);  // two openings in one run
          ++e;
        }
        const Step& last = l.steps[(k0 + e) % n];
        const Step& after = l.steps[(k0 + e + 1) % n];
        const SectionPiece& ps = trace_.pieces[static_cast<std::size_t>(st.piece)];
        const SectionPiece& pl = trace_.pieces[static_cast<std::size_t>(last.piece)];
        ends[name].push_back({st.forward ? ps.first : ps.last, trace_.pieces[static_cast<std::size_t>(before.piece)].face});
        ends[name].push_back({last.forward ? pl.last : pl.first, trace_.pieces[static_cast<std::size_t>(after.piece)].face});
      }
    }
    for (auto& [name, es] : ends) {
      if (failed.count(name)) continue;
      std::vector<char> grouped(es.size(), 0);
      std::vector<SectionPiece> bridges;
      for (std::size_t a = 0; a < es.size() && !failed.count(name); ++a) {
        if (grouped[a]) continue;
        std::vector<std::size_t> group{a};
        for (std::size_t b = a + 1; b < es.size(); ++b)
          if (!grouped[b] && body_.same_surface(es[a].wall_face, es[b].wall_face)) group.push_back(b);
        for (std::size_t g : group) grouped[g] = 1;
        std::optional<SectionPiece> br;
        if (group.size() == 2) br = bridge(es[group[0]], es[group[1]]);
        if (br) bridges.push_back(std::move(*br));
        else failed.insert(name);
      }
      if (!failed.count(name))
        for (SectionPiece& b : bridges) trace_.pieces.push_back(std::move(b));
    }
    unclosed += static_cast<int>(failed.size());
    std::set<std::string> closed;
    for (const std::string& n : names)
      if (!failed.count(n)) closed.insert(n);
    return closed;
  }

  template <class End>
  std::optional<SectionPiece> bridge(const End& a, const End& b) {
    const auto va = vertex_of_.find({a.crossing, a.wall_face}), vb = vertex_of_.find({b.crossing, b.wall_face});
    if (va == vertex_of_.end() || vb == vertex_of_.end()) return std::nullopt;
    return trace_bridge(body_, trace_.vertices[static_cast<std::size_t>(va->second)],
                        trace_.vertices[static_cast<std::size_t>(vb->second)], trace_, s_);
  }

  void measure(Loop& l) const {
    double green = 0;
    for (const Step& st : l.steps) {
      const SectionPiece& p = trace_.pieces[static_cast<std::size_t>(st.piece)];
      green += st.forward ? p.green : -p.green;
      l.length += p.length;
      const std::size_t n = p.points.size();
      for (std::size_t k = 1; k < n; ++k) l.polygon.push_back(s_.drawing(p.points[st.forward ? k : n - 1 - k]));
    }
    l.area = 0.5 * std::abs(green);
  }

  const SectionBody& body_;
  SpanSurfaceEvaluator& s_;
  SectionTrace trace_;
  std::map<std::pair<int, int>, int> vertex_of_;  // (crossing, face) -> vertex
};

// The passage name of a cavity loop: its walls' passages joined, "cavity" without any.
std::string cavity_name(const BodySection& b, const Loop& l) {
  std::set<std::string> names;
  for (const Step& st : l.steps) {
    const std::string p = passage_of_face(b.face_name(st.piece));
    if (!p.empty()) names.insert(p);
  }
  std::vector<std::string> sorted(names.begin(), names.end());
  std::sort(sorted.begin(), sorted.end(), natural_less);
  std::string out;
  for (const std::string& n : sorted) out += (out.empty() ? "" : " + ") + n;
  return out.empty() ? "cavity" : out;
}

void set_depths(std::vector<Loop>& loops) {
  for (Loop& l : loops)
    for (const Loop& o : loops)
      if (&o != &l && o.area > l.area && !l.polygon.empty() && inside(o.polygon, l.polygon.front())) ++l.depth;
}

SpanSection section_at(const std::vector<SectionBody>& bodies, const SpanSurface& surface, std::vector<FaceClassifiers>& cls) {
  SpanSurfaceEvaluator s(surface);
  SpanSection out;
  out.span = surface.span;
  std::vector<std::vector<Loop>> sealed(bodies.size());
  std::vector<Loop> holes;
  std::vector<Loop> cavities;  // body 0
  std::vector<std::string> cavity_names;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    BodySection bs(bodies[b], s, cls[b]);
    std::vector<Loop> h;
    bs.loops(sealed[b], h, out.unclosed_openings);
    for (const SectionPiece& p : bs.trace().pieces) {
      if (p.bridge) continue;
      SectionCurve c{static_cast<int>(b), bodies[b].shape->faces[static_cast<std::size_t>(p.face)].name, {}};
      for (const Vec3& q : p.points) c.points.push_back(s.drawing(q));
      out.curves.push_back(std::move(c));
    }
    set_depths(sealed[b]);
    for (Loop& l : sealed[b]) {
      l.kind = l.depth == 0 ? SectionLoopKind::Outer : (l.depth % 2 ? SectionLoopKind::Cavity : SectionLoopKind::Island);
      if (b == 0 && l.kind == SectionLoopKind::Cavity) l.name = cavity_name(bs, l);
      out.metal_area += (l.depth % 2 ? -1 : 1) * l.area;
    }
    for (Loop& l : h) {
      l.kind = SectionLoopKind::Hole;
      l.depth = 1;
      out.metal_area -= l.area;
      out.holes.push_back({l.name, l.area, centroid(l.polygon)});
      holes.push_back(std::move(l));
    }
  }
  // Passages: body 0's cavities, minus islands and other bodies' metal inside, by name.
  std::map<std::string, SectionPassage> passages;
  std::map<std::string, double> largest;
  for (const Loop& l : sealed.front()) {
    if (l.kind != SectionLoopKind::Cavity) continue;
    SectionPassage& p = passages[l.name];
    p.name = l.name;
    ++p.loops;
    p.area += l.area;
    p.wetted_perimeter += l.length;
    if (l.area > largest[l.name]) {
      largest[l.name] = l.area;
      p.centroid = centroid(l.polygon);
    }
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (const Loop& m : sealed[b]) {
        const bool island = b == 0 && m.depth == l.depth + 1, other = b > 0;
        if ((!island && !other) || m.polygon.empty() || !inside(l.polygon, m.polygon.front())) continue;
        p.area += (other && m.depth % 2 ? 1 : -1) * m.area;
        p.wetted_perimeter += m.length;
      }
  }
  for (auto& [name, p] : passages) {
    p.hydraulic_diameter = p.wetted_perimeter > 0 ? 4 * p.area / p.wetted_perimeter : 0;
    out.passages.push_back(p);
  }
  std::sort(out.passages.begin(), out.passages.end(), [](const SectionPassage& a, const SectionPassage& b) { return natural_less(a.name, b.name); });
  // Holes of one name summed (a hole cut twice), in name order.
  std::map<std::string, SectionHole> by_name;
  for (const SectionHole& h : out.holes) {
    SectionHole& t = by_name[h.name];
    if (t.name.empty()) t = h;
    else t.area += h.area;
  }
  out.holes.clear();
  for (auto& [n, h] : by_name) out.holes.push_back(h);
  std::sort(out.holes.begin(), out.holes.end(), [](const SectionHole& a, const SectionHole& b) { return natural_less(a.name, b.name); });
  const Loop* outer = nullptr;
  for (const Loop& l : sealed.front())
    if (l.kind == SectionLoopKind::Outer && (!outer || l.area > outer->area)) outer = &l;
  if (outer && !outer->polygon.empty()) {
    std::tie(out.chord_a, out.chord_b) = diameter(outer->polygon);
    out.chord = (out.chord_a - out.chord_b).norm();
  }
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (Loop& l : sealed[b]) out.loops.push_back({static_cast<int>(b), l.kind, std::move(l.polygon), l.area, l.length, l.depth, l.name});
  for (Loop& l : holes) out.loops.push_back({0, l.kind, std::move(l.polygon), l.area, l.length, l.depth, l.name});
  return out;
}

}  // namespace

bool is_opening_face(const std::string& name) {
  const std::string kind = brep::feature_kind(name);
  return kind == "film_row" || kind == "showerhead" || kind == "te_slot";
}

std::string passage_of_face(const std::string& name) {
  if (name.rfind("chamber_", 0) == 0 && name.size() > 13 && name.compare(name.size() - 5, 5, "_wall") == 0)
    return name.substr(0, name.size() - 5);
  const std::string kind = brep::feature_kind(name);
  if (kind == "radial_passage" || kind == "inlet") return name;  // an inlet through the hub floor is a passage too
  return "";
}

std::vector<SpanSection> span_sections(const brep::Part& part, const std::vector<SpanSurface>& surfaces) {
  std::vector<SectionBody> bodies;
  for (const brep::NamedBody& b : part) bodies.emplace_back(b.geometry);
  std::vector<SpanSection> out(surfaces.size());
  const int workers = std::min(parallel_workers(), static_cast<int>(std::max<std::size_t>(1, surfaces.size())));
  std::vector<std::vector<FaceClassifiers>> cls(static_cast<std::size_t>(workers));
  for (auto& w : cls)
    for (const SectionBody& b : bodies) w.emplace_back(b);
  parallel_for(static_cast<int>(surfaces.size()), workers, [&](int k, int w) {
    out[static_cast<std::size_t>(k)] = section_at(bodies, surfaces[static_cast<std::size_t>(k)], cls[static_cast<std::size_t>(w)]);
  });
  return out;
}

}  // namespace cg::features
