#pragma once
// STEP export of a solid with named faces (XCAF document + STEPCAFControl_Writer), unit mm.
#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <string>
#include <vector>

#include "src/brep/blade_solid.hpp"

namespace cg::io {

enum class StepSchema { AP214, AP242 };

/// "AP214" | "AP242" (case-insensitive) -> schema; throws InvalidGeometry otherwise.
StepSchema parse_step_schema(const std::string& name);
const char* step_schema_name(StepSchema schema);

struct StepOptions {
  StepSchema schema = StepSchema::AP214;  ///< AP214IS (default) or AP242DIS
  std::string product_name = "blade";     ///< name of the product / shape in the file
};

/// Writes `shape` to `file` (unit mm) with each face of `faces` named (ADVANCED_FACE names), through a
/// temporary file that is renamed on success (write_atomically). Throws ExportError on failure.
/// Sets OCCT's global STEP parameters (write.step.schema, write.step.unit, write.stepcaf.subshapes.name).
void write_step(const std::filesystem::path& file, const TopoDS_Shape& shape, const std::vector<brep::NamedFace>& faces,
                const StepOptions& options = {});

}  // namespace cg::io
