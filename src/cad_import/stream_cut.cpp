#include "src/cad_import/stream_cut.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <limits>

#include "adaptors/occt_convert.hpp"
#include "src/core/error.hpp"

namespace cg::cad_import {
namespace {

using Polyline = std::vector<Eigen::Vector3d>;

Polyline sampled(const TopoDS_Edge& edge, double chord_error) {
  const BRepAdaptor_Curve c(edge);
  Polyline out;
  GCPnts_QuasiUniformDeflection d(c, chord_error, c.FirstParameter(), c.LastParameter());
  if (d.IsDone() && d.NbPoints() >= 2) {
    for (int i = 1; i <= d.NbPoints(); ++i) out.push_back(occt::to_eigen(d.Value(i)));
    return out;
  }
  GCPnts_UniformAbscissa u(c, 64, c.FirstParameter(), c.LastParameter());
  if (!u.IsDone()) throw AlgorithmFailure("cannot sample a section edge of the blade");
  for (int i = 1; i <= u.NbPoints(); ++i) out.push_back(occt::to_eigen(c.Value(u.Parameter(i))));
  return out;
}

double length(const Polyline& p) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) s += (p[i + 1] - p[i]).norm();
  return s;
}

// Chains the pieces end to end (either direction), starting each chain at an unused piece.
void chain(std::vector<Polyline> pieces, double gap, StreamCut& out) {
  std::vector<bool> used(pieces.size(), false);
  for (std::size_t start = 0; start < pieces.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    Polyline c = pieces[start];
    for (;;) {
      if (c.size() > 2 && (c.back() - c.front()).norm() <= gap && length(c) > 10 * gap) {
        c.pop_back();
        out.closed.push_back(std::move(c));
        break;
      }
      std::size_t best = pieces.size();
      bool reversed = false;
      double d_best = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < pieces.size(); ++j) {
        if (used[j]) continue;
        const double df = (pieces[j].front() - c.back()).norm(), db = (pieces[j].back() - c.back()).norm();
        if (std::min(df, db) < d_best) best = j, d_best = std::min(df, db), reversed = db < df;
      }
      if (best == pieces.size() || d_best > gap) {
        out.open.push_back(std::move(c));
        break;
      }
      used[best] = true;
      Polyline& p = pieces[best];
      if (reversed) std::reverse(p.begin(), p.end());
      c.insert(c.end(), p.begin() + 1, p.end());
    }
  }
}

}  // namespace

StreamCut cut_faces(const TopoDS_Shape& faces, const TopoDS_Shape& surface, double gap, double chord_error) {
  StreamCut out;
  std::vector<Polyline> pieces;
  try {
    BRepAlgoAPI_Section section(faces, surface, Standard_False);
    section.Approximation(Standard_True);
    section.Build();
    if (!section.IsDone()) throw AlgorithmFailure("OCCT's section of the blade's faces by a stream surface failed");
    for (TopExp_Explorer e(section.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
      pieces.push_back(sampled(TopoDS::Edge(e.Current()), chord_error));
      ++out.edges;
    }
  } catch (const Standard_Failure& e) {
    throw AlgorithmFailure(std::string("OCCT's section of the blade's faces by a stream surface failed: ") + e.GetMessageString());
  }
  chain(std::move(pieces), gap, out);
  return out;
}

}  // namespace cg::cad_import
