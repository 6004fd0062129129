#include "src/cad_import/cad_blade.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <gp_Pln.hxx>
#include <TopoDS_Compound.hxx>

#include <optional>

#include "src/blade_import/channel_side.hpp"
#include "src/blade_import/table_blade.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/cad_import/face_samples.hpp"
#include "src/cad_import/stream_cut.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::cad_import {
namespace {

using blade_import::ChannelSide;
using blade_import::RowKind;

// The stream surfaces of the flow path: planes z = s * span, or the streamlines' surfaces of revolution.
struct StreamSurfaces {
  double span = 0;                        // cascade
  std::optional<blade::MeridionalNet> net;  // annular
  std::optional<ChannelSide> side;

  double theta0 = 0, width = 2 * kPi;   // annular: the angular sector the blade's faces lie in (rad)

  // The stream surface at s: a face on the plane, or on the surface of revolution over the sector only
  // (a smaller face makes OCCT's section ~2x faster).
  TopoDS_Shape at(double s) const {
    if (!net) return BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, s * span), gp::DZ())).Face();
    const BSplineCurve<2> c = net->streamline_at(s).curve();
    const auto rev = brep::revolved_surface(brep::RevolvedTrim{c}, theta0, "the stream surface");
    BRepBuilderAPI_MakeFace mk(rev, 0.0, width, c.first_param(), c.last_param(), Precision::Confusion());
    if (!mk.IsDone()) throw AlgorithmFailure("cannot make the face of a stream surface");
    return mk.Face();
  }
  // The sector of the given points, with a margin; the whole turn when they spread over more than 0.6 pi.
  void set_sector(const std::vector<SampledFace>& faces) {
    if (!net) return;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const SampledFace& f : faces)
      for (const Eigen::Vector3d& p : f.points) mean += Eigen::Vector2d(p.y(), p.z()).normalized();
    const double centre = std::atan2(mean.y(), mean.x());
    double lo = 0, hi = 0;
    for (const SampledFace& f : faces)
      for (const Eigen::Vector3d& p : f.points) {
        const double d = std::remainder(std::atan2(p.z(), p.y()) - centre, 2 * kPi);
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
    if (hi - lo > 0.6 * kPi) return;
    const double margin = 0.05 + 0.25 * (hi - lo);
    theta0 = centre + lo - margin;
    width = hi - lo + 2 * margin;
  }
  // Largest hub-to-casing distance (mm), along the hub.
  double height() {
    if (!net) return span;
    double h = 0;
    const blade::Streamline& hub = net->hub();
    for (int i = 0; i <= 32; ++i) {
      const Eigen::Vector2d p = hub.point(hub.first_param() + (hub.last_param() - hub.first_param()) * i / 32);
      h = std::max(h, -side->offset(Eigen::Vector3d(p.x(), p.y(), 0), 1));
    }
    return h;
  }
};

StreamSurfaces stream_surfaces(RowKind kind, const std::vector<Eigen::Vector2d>& casing, const blade::MeridionalNetDefinition* channel,
                               const std::vector<Eigen::Vector2d>& hub) {
  StreamSurfaces s;
  if (kind == RowKind::Cascade) {
    s.span = casing.front().y();
    s.side.emplace(s.span);
    return s;
  }
  blade::MeridionalNetDefinition def = *channel;  // its streamlines; the LE line is the import's
  def.hub = hub;
  def.casing = casing;
  def.leading_edge.clear();
  def.trailing_edge.clear();
  def.stations.clear();
  s.net.emplace(def);
  s.side.emplace(*s.net);
  return s;
}

std::string point_text(const Eigen::Vector3d& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) + ") mm";
}

// The one closed outline of the cut at span s, or an error naming the file and the span.
std::vector<Eigen::Vector3d> outline(const StreamCut& cut, const std::string& path, double s, int i, int n) {
  const std::string at = path + ": the cut at span " + format_number(s);
  if (cut.closed.empty() && cut.open.empty()) {
    if (i == 0 || i == n - 1)
      throw InvalidGeometry(path + ": the blade does not reach the " + (i == 0 ? "hub" : "casing") + ": its cut at span " +
                            format_number(s) + " meets none of its faces; the blade must reach to or past hub and casing");
    throw InvalidGeometry(at + " meets none of its faces (the blade is not one wall from hub to casing)");
  }
  if (!cut.open.empty())
    throw InvalidGeometry(at + " is not one closed outline: it ends open at " + point_text(cut.open.front().back()) +
                          " (faces more than blade.import.tolerance apart, or a blade that is not one closed wall)");
  if (cut.closed.size() != 1)
    throw InvalidGeometry(at + " is not one closed outline (" + std::to_string(cut.closed.size()) + " loops)");
  return cut.closed.front();
}

// Points of the wall faces inside the flow path, each with the cut below it.
std::vector<blade_import::SurfaceSample> surface_samples(const std::vector<SampledFace>& faces, ChannelSide& side,
                                                         const std::vector<double>& spans) {
  std::vector<blade_import::SurfaceSample> out;
  for (const SampledFace& f : faces) {
    if (f.role != FaceRole::Wall) continue;
    for (const Eigen::Vector3d& p : f.points) {
      if (side.offset(p, 0) <= 0 || side.offset(p, 1) >= 0) continue;
      std::size_t lo = 0, hi = spans.size() - 1;  // offset(p, spans[lo]) >= 0 > offset(p, spans[hi]), else the ends
      while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (side.offset(p, spans[mid]) >= 0 ? lo : hi) = mid;
      }
      out.push_back({p, lo, f.index});
    }
  }
  return out;
}

}  // namespace

blade_import::ImportedBlade read_cad_blade(const std::string& path, CadFormat format, RowKind kind,
                                           const std::vector<Eigen::Vector2d>& hub, const std::vector<Eigen::Vector2d>& casing,
                                           const blade::MeridionalNetDefinition* channel, const CadCutOptions& o) {
  const TopoDS_Shape shape = read_cad_shape(path, format);
  StreamSurfaces surfaces = stream_surfaces(kind, casing, channel, hub);
  const std::vector<SampledFace> faces = sample_faces(shape, o.face_samples, *surfaces.side, o.tolerance);
  TopoDS_Compound walls;
  BRep_Builder builder;
  builder.MakeCompound(walls);
  int wall_faces = 0;
  for (const SampledFace& f : faces)
    if (f.role == FaceRole::Wall) builder.Add(walls, f.face), ++wall_faces;
  if (wall_faces == 0) throw InvalidGeometry(path + ": every face lies on the hub or the casing; no blade wall is left");
  surfaces.set_sector(faces);

  // Interior cuts are moved off round span fractions (by 1.37 % of their spacing), where CAD faces are
  // often split: a cut along a face boundary would be ambiguous.
  const double inset = 0.25 * o.tolerance / surfaces.height();
  std::vector<double> spans;
  for (int i = 0; i < o.cuts; ++i)
    spans.push_back(i == 0 ? inset : i == o.cuts - 1 ? 1 - inset : (i + 0.0137) / (o.cuts - 1));
  std::vector<blade_import::SectionTable> tables(spans.size());
  std::vector<int> order{0, o.cuts - 1};  // the ends first: a blade short of hub or casing is named so
  for (int i = 1; i + 1 < o.cuts; ++i) order.push_back(i);
  for (const int i : order) {
    const double s = spans[static_cast<std::size_t>(i)];
    const StreamCut cut = cut_faces(walls, surfaces.at(s), o.tolerance, o.chord_error);
    blade_import::SectionTable& t = tables[static_cast<std::size_t>(i)];
    t.file = path + " (cut at span " + format_number(s) + ", point number as line)";
    t.points = outline(cut, path, s, i, o.cuts);
    for (std::size_t k = 0; k < t.points.size(); ++k) t.lines.push_back(static_cast<int>(k) + 1);
  }
  blade_import::ImportedBlade b = blade_import::blade_from_tables(tables, kind, hub, casing, o.edges);
  b.file = path;
  b.surface_samples = surface_samples(faces, *surfaces.side, spans);
  return b;
}

}  // namespace cg::cad_import
