#include "features/passages/radial_passages.hpp"

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <sstream>

#include "src/brep/naming/face_names.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {

RadialPassageBuild build_radial_passages(const blade::BladeModel& model,
                                         const std::vector<RadialPassageDefinition>& passages) {
  RadialPassageBuild out;
  if (passages.empty()) return out;
  if (!model.trim.straight)
    throw PassageInputError("radial_passages", "radial passages are supported on straight vanes only "
                                               "(flow_path.type \"straight\")");
  const blade::BladeCoordinates coords(model);
  const double z0 = model.trim.hub_z, z1 = model.trim.casing_z, span = z1 - z0;
  const double ob = model.options.overbuild * span;  // the tool passes the end planes by half of it
  for (std::size_t k = 0; k < passages.size(); ++k) {
    const RadialPassageDefinition& p = passages[k];
    const std::string field = "radial_passages[" + std::to_string(k) + "]";
    const double r = 0.5 * p.diameter;
    double wall = HUGE_VAL;
    for (double s : {0.0, 0.5, 1.0}) {
      const Eigen::Vector3d c(p.position.x(), p.position.y(), z0 + s * span);
      const blade::BladeLocateResult loc = coords.locate(c);
      // depth > 0: inside the blade, at that distance from the wall.
      const double d = loc.found ? loc.coordinate.depth : -HUGE_VAL;
      if (!(d > r))
        throw PassageInputError(field + ".position", "radial passage " + std::to_string(k + 1) + " (diameter " +
                                                         format_number(p.diameter) + " mm at [" + format_number(p.position.x()) + ", " +
                                                         format_number(p.position.y()) + "] mm) breaks through the wall at span " +
                                                         format_number(s) + ": its axis is " + format_number(d) + " mm inside the wall");
      wall = std::min(wall, d - r);
    }
    for (std::size_t j = 0; j < k; ++j)
      if ((passages[j].position - p.position).norm() < 0.5 * (passages[j].diameter + p.diameter))
        throw PassageInputError(field + ".position", "radial passages " + std::to_string(j + 1) + " and " +
                                                         std::to_string(k + 1) + " overlap");
    const gp_Ax2 ax(gp_Pnt(p.position.x(), p.position.y(), z0 - 0.5 * ob), gp::DZ());
    BRepPrimAPI_MakeCylinder cyl(ax, r, span + ob);
    cyl.Build();
    if (!cyl.IsDone()) throw FeatureFailure("radial passage " + std::to_string(k + 1) + ": cannot make its cylinder");
    FeatureTool t;
    t.feature = "radial_passage_" + std::to_string(k + 1);
    t.shape.shape = cyl.Shape();
    for (const TopoDS_Shape& f : faces_of(t.shape.shape)) t.shape.faces.push_back({TopoDS::Face(f), t.feature});
    t.expected_volume = kPi * r * r * span;  // through the whole span between the end planes
    out.tools.push_back(t);
    out.min_wall.push_back(wall);
  }
  return out;
}

}  // namespace cg::features
