#include "src/blade/span_section.hpp"

#include <cmath>
#include <utility>

#include "src/blade/surface_iso.hpp"

namespace cg::blade {

SpanSection::SpanSection(const BladeModel& model, double span)
    : span_(span),
      u_te_(model.u_te),
      curve_(std::make_shared<const BSplineCurve<3>>(detail::iso_curve_v(model.surface, span))),
      map_(*curve_, model.u_le, model.u_te) {}

SpanSection::SpanSection(const BladeModel& model, double span, std::shared_ptr<const IsoArcLengthNodes> nodes)
    : span_(span),
      u_te_(model.u_te),
      curve_(std::make_shared<const BSplineCurve<3>>(detail::iso_curve_v(model.surface, span))),
      map_(*curve_, model.u_le, model.u_te, IsoArcLength(*curve_, std::move(nodes))) {}

double SpanSection::u_at_chordwise(double c, ChordAccuracy accuracy) const {
  const double u = map_.param_at(c, accuracy);
  return u - std::floor(u);
}

double SpanSection::seam_chordwise() const {
  if (u_te_ == 0) return 1.0;  // the seam is the TE itself
  return map_.chordwise_at(0.0);
}

}  // namespace cg::blade
