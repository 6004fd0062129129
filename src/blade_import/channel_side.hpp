#pragma once
// Where a point lies relative to the stream surfaces of a flow path (internal to the import): the
// signed distance from the stream surface at span s, positive towards the casing. Annular: in the
// meridional plane, from the streamline at s (global projection; the streamline of each span asked for
// is kept); straight: z - s * span.
#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>

#include "src/algo/project_point_curve.hpp"
#include "src/blade/meridional_net.hpp"

namespace cg::blade_import {

class ChannelSide {
 public:
  /// Straight flow path of the given span (mm).
  explicit ChannelSide(double span) : span_(span) {}
  /// Meridional flow path (the net is copied).
  explicit ChannelSide(const blade::MeridionalNet& net);

  /// Signed distance (mm) of P from the stream surface at span s, > 0 on the casing side. Points
  /// beyond the streamline's ends are measured from its end's normal line.
  double offset(const Eigen::Vector3d& P, double s);
  /// The streamline at s (meridional only).
  const blade::Streamline& streamline(double s);

 private:
  struct Line {
    blade::Streamline line;
    std::unique_ptr<CurveProjector<2>> projector;
  };
  Line& line(double s);
  double span_ = 0;
  std::optional<blade::MeridionalNet> net_;
  std::map<double, Line> lines_;
  double sign_ = 1;  // orientation of the streamlines' left normal towards the casing
};

}  // namespace cg::blade_import
