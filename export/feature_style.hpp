#pragma once
// One mapping from feature kinds (brep::feature_kind of a face name) to what every exporter uses to
// group and show them: a stable numeric id (VTK cell data, IGES level, gmsh physical group) and a
// colour (STEP/IGES colours, preview, section drawing). Ids are assigned in order of first appearance
// in the part, so the same part always gets the same ids; colours come from a fixed table per known
// kind (the naming scheme of src/brep/named_shape.hpp) so a chamber looks the same in every file.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"

namespace cg::io {

/// sRGB colour, components in [0, 1].
using Colour = std::array<double, 3>;

/// The colour of a feature kind: fixed for the kinds of the naming scheme, a stable hash-derived
/// hue for any other kind (so new features get a colour without touching this table).
Colour kind_colour(const std::string& kind);

/// "#rrggbb" of a colour (SVG, Markdown).
std::string hex_colour(const Colour& c);

/// The kinds present in a part, their ids and the face names of each kind.
struct FeatureTable {
  std::vector<std::string> kinds;                  ///< id k -> kind, order of first appearance (blade faces first)
  std::map<std::string, int> id_of_kind;           ///< kind -> id (0-based)
  std::vector<std::string> names;                  ///< every distinct face name, sorted
  std::map<std::string, int> id_of_name;           ///< face name -> index into `names`

  int kind_id(const std::string& face_name) const { return id_of_kind.at(brep::feature_kind(face_name)); }
  int name_id(const std::string& face_name) const { return id_of_name.at(face_name); }
};

/// The feature table of all faces of all bodies of `part`.
FeatureTable feature_table(const brep::Part& part);

}  // namespace cg::io
