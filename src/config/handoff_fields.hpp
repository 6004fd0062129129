#pragma once
// Config fields of the hand-off outputs ("output": formats, STL deflection, section spans) and of the
// mesh command ("mesh"), read with the typed, range-checked Field reader. Schema:
// data/schema/coolinggen.schema.json (definitions output_options, mesh_options).
#include <set>
#include <vector>

#include "export/outputs.hpp"
#include "src/config/json_fields.hpp"
#include "src/mesh/mesh_options.hpp"

namespace cg::config {

/// The hand-off fields of "output" (the caller checks the allowed keys: kHandoffOutputKeys).
struct HandoffOutputFields {
  std::set<io::OutputFormat> formats = io::all_output_formats();
  double stl_deflection = 0.01;            ///< mm
  double stl_angular_deflection_deg = 20;  ///< deg
  std::vector<double> section_spans = {0.1, 0.3, 0.5, 0.7, 0.9};
};

/// Reads "formats", "stl_deflection", "stl_angular_deflection_deg", "section_spans" of `output`.
HandoffOutputFields handoff_output_fields(const Field& output);

/// Reads the "mesh" object.
mesh::MeshOptions mesh_options(const Field& mesh);

}  // namespace cg::config
