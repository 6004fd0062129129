#include "export/cgns_file.hpp"

#include <cgnslib.h>

namespace cg::io {

void cgns_check(int status, const std::string& what) {
  if (status != CG_OK) throw ExportError("CGNS: " + what + ": " + cg_get_error());
}

CgnsFile::CgnsFile(const std::filesystem::path& path) {
  cgns_check(cg_open(path.c_str(), CG_MODE_WRITE, &fn_), "open " + path.string());
  open_ = true;
}

CgnsFile::~CgnsFile() {
  if (open_) cg_close(fn_);
}

void CgnsFile::close() {
  open_ = false;
  cgns_check(cg_close(fn_), "close");
}

int CgnsFile::write_base(const std::string& name, int cell_dimension, int physical_dimension) {
  int B = 0;
  cgns_check(cg_base_write(fn_, name.c_str(), cell_dimension, physical_dimension, &B), "base " + name);
  cgns_check(cg_goto(fn_, B, "end"), "goto base");
  cgns_check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "data class");
  cgns_check(cg_units_write(CGNS_ENUMV(MassUnitsNull), CGNS_ENUMV(Millimeter), CGNS_ENUMV(TimeUnitsNull),
                            CGNS_ENUMV(TemperatureUnitsNull), CGNS_ENUMV(Degree)),
             "units");
  return B;
}

void CgnsFile::write_coordinate(int B, int Z, const char* name, const std::vector<double>& values) {
  int C = 0;
  cgns_check(cg_coord_write(fn_, B, Z, CGNS_ENUMV(RealDouble), name, values.data(), &C), name);
  cgns_check(cg_goto(fn_, B, "Zone_t", Z, "GridCoordinates_t", 1, "DataArray_t", C, "end"), std::string("goto ") + name);
  const float length[5] = {0, 1, 0, 0, 0};  // mass, length, time, temperature, angle
  cgns_check(cg_exponents_write(CGNS_ENUMV(RealSingle), length), std::string("exponents of ") + name);
}

}  // namespace cg::io
