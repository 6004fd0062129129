#pragma once
// The coolant domain of a cooled blade and the conformal compound of all domains for meshing.
//
// Coolant = uncooled blade solid minus the cooled blade and its inserts: every cavity the cooling
// features removed (chambers, turnarounds, slots, film holes up to the outer wall) as one fluid region
// (BRepAlgoAPI_Cut with history). Its faces carry the names of the metal faces they touch (the
// fluid-solid interfaces: "chamber_1_wall", "film_row_1_hole_003", "insert_1") and, where the fluid
// meets the blade envelope (chamber inlets on the hub, film hole exits on the wall), "coolant_opening_"
// + the envelope face's name ("coolant_opening_hub", "coolant_opening_blade_wall").
//
// The domains are then joined by one general fuse (BOPAlgo_Builder) so metal and coolant share their
// interface faces: a mesh of the compound is conformal across the interface (what conjugate heat
// transfer needs). Every face of the compound is named from the fuse's history.
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"
#include "src/core/error.hpp"

namespace cg::mesh {

/// Meshing could not be done (bad input, a failed boolean, gmsh failure); the message says which step.
class MeshError : public Error {
 public:
  using Error::Error;
};

/// The coolant solid(s) with named faces; empty `shape` when the blade has no cavities.
struct CoolantDomain {
  TopoDS_Shape shape;                  ///< solid or compound of solids (one per separate cavity)
  std::vector<brep::NamedFace> faces;  ///< every face of `shape`
  double volume = 0;                   ///< mm^3, BRepGProp (1e-7 relative accuracy)
  double removed_volume = 0;           ///< V(uncooled) - V(blade), mm^3: what the features removed
  int solids = 0;
};

/// Computes the coolant domain. `uncooled` is the blade solid before the cooling features, its faces
/// named in `uncooled_faces` (empty: openings are all named "coolant_opening"). Throws MeshError when the cut fails or a face gets no name.
CoolantDomain coolant_domain(const brep::Part& part, const TopoDS_Shape& uncooled,
                             const std::vector<brep::NamedFace>& uncooled_faces);

/// One region of the compound to mesh: a body of the part or the coolant.
struct Region {
  std::string name;  ///< body name ("blade", "insert_1") or "coolant"
  bool fluid = false;
  std::vector<TopoDS_Shape> solids;  ///< solids of the compound that belong to it
};

/// Metal and coolant joined with shared interface faces.
struct ConformalDomains {
  TopoDS_Compound compound;
  std::vector<Region> regions;
  std::vector<brep::NamedFace> faces;  ///< every face of the compound once; interfaces named by the metal side
};

/// General fuse of the part's bodies and the coolant (when not empty). Throws MeshError on failure.
ConformalDomains conformal_domains(const brep::Part& part, const CoolantDomain& coolant);

}  // namespace cg::mesh
