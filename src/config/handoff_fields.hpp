#pragma once
// Config fields of the hand-off outputs ("output": STL deflection, section spans) and of the mesh
// command ("mesh"), read with the typed, range-checked Field reader into plain structs
// (src/config/config.hpp). Schema: data/schema/coolinggen.schema.json (output_options, mesh_options).
#include "src/config/config.hpp"
#include "src/config/json_fields.hpp"

namespace cg::config {

/// Reads "stl_deflection", "stl_angular_deflection_deg", "section_spans" of `output` into `o`.
void read_handoff_output_fields(const Field& output, OutputOptions& o);

/// Reads the "mesh" object.
MeshConfig mesh_config(const Field& mesh);

}  // namespace cg::config
