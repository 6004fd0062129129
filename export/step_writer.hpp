#pragma once
// STEP export of a brep::Part through XCAF (STEPCAFControl_Writer), unit mm: one product (the part)
// holding one named solid per body, every face named and coloured per feature kind
// (export/part_document.hpp), and a real header (file name = product name, originating system and
// preprocessor = coolinggen and its version, OCCT version in the description).
#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"

namespace cg::io {

enum class StepSchema { AP214, AP242 };

/// "AP214" | "AP242" (case-insensitive) -> schema; throws InvalidGeometry otherwise.
StepSchema parse_step_schema(const std::string& name);
const char* step_schema_name(StepSchema schema);

struct StepOptions {
  StepSchema schema = StepSchema::AP242;  ///< AP242DIS (default) or AP214IS
  std::string product_name = "blade";     ///< name of the product in the file and in its header
};

/// Writes `part` to `file` through a temporary file renamed on success (write_atomically).
/// Throws ExportError on failure (empty part, a body that is not one solid, a face not of its body).
/// Sets OCCT's global STEP parameters (write.step.schema, write.step.unit, write.stepcaf.subshapes.name).
void write_step(const std::filesystem::path& file, const brep::Part& part, const StepOptions& options = {});

/// One body named "blade": write_step(file, {{"blade", {shape, faces}}}, options).
void write_step(const std::filesystem::path& file, const TopoDS_Shape& shape, const std::vector<brep::NamedFace>& faces,
                const StepOptions& options = {});

}  // namespace cg::io
