#pragma once
// glTF 2.0 binary (blade.glb) of a brep::Part for viewing (report.html, any glTF viewer): the XCAF
// document of the STEP file (export/part_document.hpp) on a copy of the part meshed at a viewing
// tessellation (coarser than the STL's), written by OCCT's RWGltf_CafWriter in metres with Y up (glTF's
// axes; OCCT writes raw millimetres and Z up unless told), one primitive per face, each face with the
// material of its feature kind (the colour of export/feature_style.hpp, metallic 0; the writer names
// materials mat_<n>).
// glTF has no face names: GltfModel::faces maps primitive i (mesh 0, in file order) to its face.
#include <filesystem>
#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"

namespace cg::io {

struct GltfOptions {
  std::string product_name = "blade";  ///< the node's and the mesh's name
  /// mm, > 0; at least kGltfRelativeDeflection of the part's diagonal is used.
  double linear_deflection = 0.05;
  double angular_deflection = 0.5;     ///< rad, > 0
};

/// Floor of the viewing deflection relative to the part's diagonal (as the STL's: it keeps a 100 m
/// vane meshable; a face that still gets no triangles is meshed again, finer).
inline constexpr double kGltfRelativeDeflection = 2e-5;

/// One primitive of the .glb: the face it shows.
struct GltfFace {
  std::string body;   ///< "blade", "insert_1"
  std::string name;   ///< feature name of the face
  std::string kind;   ///< brep::feature_kind(name)
  double area = 0;    ///< mm^2 (BRepGProp through brep::integrate_solid)
};

struct GltfModel {
  std::string glb;              ///< the file's bytes
  std::vector<GltfFace> faces;  ///< one per primitive, in file order
  std::size_t triangles = 0;
  double deflection = 0;        ///< mm, the linear deflection used
};

/// Meshes a copy of `part` and renders it as .glb bytes. Throws ExportError (empty part, a face that
/// gets no triangles, the writer fails).
GltfModel make_gltf(const brep::Part& part, const GltfOptions& options = {});

/// Writes model.glb to `file` atomically. Throws ExportError.
void write_glb(const std::filesystem::path& file, const GltfModel& model);

}  // namespace cg::io
