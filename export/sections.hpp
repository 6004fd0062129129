#pragma once
// Sections of a brep::Part at several spans, for the section drawing and the design-check tables.
//
// A section is the intersection of every body with a cutting surface (BRepAlgoAPI_Section, which keeps
// for each section edge the face it lies on, hence its feature name): a plane for a straight vane
// (z = span height) or, for a meridional blade, the surface of revolution of the streamline at that
// span, drawn unrolled as (x, r theta) in mm — the blade-to-blade view turbine designers use. The
// edges are chained into closed loops; per body, loops nested an odd number of times bound holes in
// the metal. Cavities of the blade (loops directly inside its outer loop) are the coolant passages:
// area (minus the metal of any insert inside), wetted perimeter (including the insert's loops) and
// hydraulic diameter D_h = 4 A / P.
#include <nlohmann/json.hpp>

#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::io {

/// Plane through `origin` with unit `normal`; drawing coordinates ((p - o).x_axis, (p - o).(normal x x_axis)).
struct PlaneCut {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
};

/// Surface of revolution of a meridional curve (x, r) about the x axis, over theta_centre +- 90 deg;
/// drawing coordinates (x, r (theta - theta_centre)).
struct RevolvedCut {
  BSplineCurve<2> meridional;
  double theta_centre = 0;  ///< rad, atan2(z, y) of the blade
};

struct SectionSurface {
  double span = 0;  ///< span fraction (label and table key)
  std::variant<PlaneCut, RevolvedCut> surface;
};

/// The cutting surfaces of a blade model at the given span fractions (each in [0, 1]).
std::vector<SectionSurface> blade_section_surfaces(const blade::BladeModel& model, const std::vector<double>& spans);

/// One section edge, drawn as a polyline.
struct SectionCurve {
  int body = 0;
  std::string name;  ///< feature name of the face it lies on
  std::vector<Eigen::Vector2d> points;
};

/// A closed chain of section curves of one body.
struct SectionLoop {
  int body = 0;
  std::vector<Eigen::Vector2d> points;  ///< closed polygon (last point != first)
  std::vector<std::string> names;       ///< feature names along the loop, by decreasing length share
  double area = 0;                      ///< mm^2, unsigned
  double perimeter = 0;                 ///< mm
  int depth = 0;                        ///< number of loops of the same body around it
};

struct Passage {
  std::string name;                 ///< the main feature name on its wall (e.g. "chamber_2_wall")
  double area = 0;                  ///< mm^2, fluid area
  double wetted_perimeter = 0;      ///< mm
  double hydraulic_diameter = 0;    ///< mm, 4 A / P
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
};

struct SectionCut {
  double span = 0;
  std::vector<SectionCurve> curves;
  std::vector<SectionLoop> loops;
  double metal_area = 0;                    ///< mm^2, all bodies
  double chord = 0;                         ///< mm, largest extent of the blade's outer loop
  Eigen::Vector2d chord_a = Eigen::Vector2d::Zero(), chord_b = Eigen::Vector2d::Zero();
  std::vector<Passage> passages;            ///< cavities of the blade body (body 0)
  int open_loops = 0;                       ///< curve chains that did not close (0 for a valid solid)
};

/// Cuts every body; curves discretised to `deflection` mm. Throws ExportError when a section fails.
std::vector<SectionCut> cut_sections(const brep::Part& part, const std::vector<SectionSurface>& surfaces,
                                     double deflection = 0.005);

/// The section table for report.json / report.md: [{"span", "chord_mm", "metal_area_mm2", "passages":
/// [{"name", "area_mm2", "wetted_perimeter_mm", "hydraulic_diameter_mm"}]}].
nlohmann::ordered_json sections_json(const std::vector<SectionCut>& cuts);

}  // namespace cg::io
