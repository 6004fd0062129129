#pragma once
// mesh.cgns: the tetrahedral mesh for a CFD code (CGNS 3.4 mid-level library, HDF5 storage).
//
// One base "coolinggen_mesh" (cell and physical dimension 3, DataClass Dimensional, DimensionalUnits
// millimetre / degree) with one unstructured zone per region ("blade", "insert_1", ..., "coolant"),
// each with its own nodes (CoordinateX/Y/Z, double, mm: an interface node is stored in both zones with
// the same coordinates), element section "Tetrahedra" (TETRA_4, elements 1..n) and one TRI_3 section
// per boundary patch of the region (src/mesh/zone_boundaries.hpp), numbered on from n + 1, normals out
// of the zone. Each patch is a BC_t of the same name (FamilySpecified, PointRange of its element range,
// GridLocation FaceCenter) whose FamilyName is the surface group (feature kind: "blade_wall", "chamber",
// "film_row", "coolant_opening_hub", ...); an interface patch also carries AdditionalFamilyName
// "Interface" = "interface_<a>_<b>" (metal region first, e.g. "interface_blade_coolant"). The patch
// name is the group's, with "_<partner>" (or "_outer") appended only when the group bounds the zone
// on more than one kind of side. Families (Family_t under the base): every group with FamilyBC BCWall,
// except the coolant openings (BCTypeUserDefined: inlet or outlet is the user's choice), and every
// interface (BCTypeUserDefined, with a Descriptor naming its zones). Each interface is also a
// ZoneGridConnectivity entry of the same name in both zones: Abutting1to1, GridLocation Vertex,
// PointList of the zone's interface nodes and PointListDonor of the same nodes in the other zone.
// Zones are written in region order; the CGNS library lists them by name when reading.
#include <string>

#include "src/mesh/mesh_files.hpp"

namespace cg::mesh {

/// Writes mesh.cgns through `files` (atomically) and returns its name. Throws MeshError when a name
/// exceeds CGNS's 32 characters or the mesh is not conformal, io::ExportError with the CGNS library's
/// message when a call fails.
std::string write_cgns_file(const FileWriter& files, const MeshData& data);

}  // namespace cg::mesh
