#pragma once
// ParaView files of a brep::Part: one `<stem>_<body>.vtp` per body (triangles, point normals) and
// `<stem>.vtm` (a multiblock listing them, block names = body names).
//
// Cell data of each .vtp: "feature_id" (the kind id of export/feature_style.hpp, the same id in every
// body), "face_name_id" (index into the "face_names" table), "face_id" (face index within its body).
// Field data: "feature_kinds" and "face_names" (string tables indexed by those ids), "body_name".
#include <filesystem>
#include <string>
#include <vector>

#include "export/triangulation.hpp"

namespace cg::io {

struct VtkFiles {
  std::filesystem::path multiblock;             ///< <stem>.vtm
  std::vector<std::filesystem::path> pieces;    ///< <stem>_<body>.vtp, in body order
};

/// One piece: the triangles of body `body` of the part as `file` (.vtp, atomically).
void write_vtk_piece(const std::filesystem::path& file, const std::string& body_name, const PartTriangles& triangles, int body);

/// The multiblock `file` (.vtm) naming the pieces `<stem>_<body>.vtp` (in its directory) of every body.
void write_vtk_multiblock(const std::filesystem::path& file, const brep::Part& part, const std::string& stem);

/// Writes the files into `dir` (each atomically; the .vtm last, so it never names a missing piece).
/// Throws ExportError on failure.
VtkFiles write_vtk(const std::filesystem::path& dir, const std::string& stem, const brep::Part& part,
                   const PartTriangles& triangles);

}  // namespace cg::io
