#include "export/stl_writer.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "export/atomic_file.hpp"
#include "export/version.hpp"

namespace cg::io {
namespace {

static_assert(sizeof(float) == 4, "binary STL needs 32-bit floats");

void put_u32(std::ofstream& out, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char*>(b), 4);
}
void put_f32(std::ofstream& out, double x) {
  const float f = static_cast<float>(x);
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(out, v);
}

}  // namespace

std::size_t write_stl(const std::filesystem::path& file, const PartTriangles& t, const std::string& product_name) {
  if (t.triangles.empty()) throw ExportError("STL: nothing to write (no triangles)");
  if (t.triangles.size() > 0xffffffffu) throw ExportError("STL: too many triangles for the binary format");
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    // The header must not start with "solid" (readers would take the file for ASCII STL).
    char header[80] = {};
    std::snprintf(header, sizeof header, "%s %s binary STL, unit mm: %s", kToolName, tool_version(), product_name.c_str());
    out.write(header, 80);
    put_u32(out, static_cast<std::uint32_t>(t.triangles.size()));
    for (const auto& tri : t.triangles) {
      const Eigen::Vector3d& a = t.points[static_cast<std::size_t>(tri[0])];
      const Eigen::Vector3d& b = t.points[static_cast<std::size_t>(tri[1])];
      const Eigen::Vector3d& c = t.points[static_cast<std::size_t>(tri[2])];
      Eigen::Vector3d n = (b - a).cross(c - a);
      if (n.norm() > 0) n.normalize();
      for (const Eigen::Vector3d* p : std::initializer_list<const Eigen::Vector3d*>{&n, &a, &b, &c})
        for (int k = 0; k < 3; ++k) put_f32(out, (*p)[k]);
      out.put(0).put(0);
    }
    out.close();
    if (!out) throw ExportError("cannot write STL file " + tmp.string());
  });
  return t.triangles.size();
}

std::size_t write_stl(const std::filesystem::path& file, const brep::Part& part, const TriangulationOptions& options,
                      const std::string& product_name) {
  return write_stl(file, triangulate_part(part, options), product_name);
}

}  // namespace cg::io
