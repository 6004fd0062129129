#pragma once
// Writing CGNS files with the CGNS mid-level library (Debian libcgns-dev, HDF5 storage): the checked
// calls, the open file and the base every CoolingGen CGNS file starts with. Used by the structured grid
// files (export/grid_cgns.hpp) and the unstructured tetrahedral meshes (src/mesh/mesh_cgns.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "export/atomic_file.hpp"

namespace cg::io {

/// Throws ExportError("CGNS: <what>: <the library's message>") unless `status` is CG_OK.
void cgns_check(int status, const std::string& what);

/// A CGNS file open for writing (CG_MODE_WRITE, replaces `path`). close() closes it with the status
/// checked; on an exception before that, the destructor closes it unchecked.
class CgnsFile {
 public:
  explicit CgnsFile(const std::filesystem::path& path);
  ~CgnsFile();
  CgnsFile(const CgnsFile&) = delete;
  CgnsFile& operator=(const CgnsFile&) = delete;

  int id() const { return fn_; }
  void close();

  /// Writes a base (name <= 32 characters) with DataClass Dimensional and DimensionalUnits millimetre
  /// and degree (mass, time and temperature null: the file holds only geometry); returns its index.
  int write_base(const std::string& name, int cell_dimension, int physical_dimension);

  /// Writes one coordinate array ("CoordinateX", ...; doubles in mm) of zone Z in base B with its
  /// DimensionalExponents (length^1), so checkers know its dimension.
  void write_coordinate(int B, int Z, const char* name, const std::vector<double>& values);

 private:
  int fn_ = 0;
  bool open_ = false;
};

}  // namespace cg::io
