#include "export/grid_cgns.hpp"

#include <cgnslib.h>

#include <array>
#include <vector>

#include "export/atomic_file.hpp"
#include "export/cgns_file.hpp"

namespace cg::io {

namespace {

CGNS_ENUMT(BCType_t) bc_type(grid::BoundaryKind k) {
  switch (k) {
    case grid::BoundaryKind::Wall: return CGNS_ENUMV(BCWall);
    case grid::BoundaryKind::Inlet: return CGNS_ENUMV(BCInflow);
    case grid::BoundaryKind::Outlet: return CGNS_ENUMV(BCOutflow);
    case grid::BoundaryKind::Farfield: return CGNS_ENUMV(BCFarfield);
  }
  return CGNS_ENUMV(BCTypeUserDefined);
}

// PointRange (1-based i, j of the first and last node) of a face range.
std::array<cgsize_t, 4> point_range(const grid::Block& b, const grid::FaceRange& r) {
  const Eigen::Vector2i p = grid::face_node(b, r, 0), q = grid::face_node(b, r, r.nodes() - 1);
  return {p.x() + 1, p.y() + 1, q.x() + 1, q.y() + 1};
}

bool is_i_face(grid::Face f) { return f == grid::Face::IMin || f == grid::Face::IMax; }
bool is_max_face(grid::Face f) { return f == grid::Face::IMax || f == grid::Face::JMax; }

// CGNS Transform of a 1-to-1 interface from `r` (this zone) to `d` (donor): for each of this zone's
// index axes, the donor axis it runs along (1 = i, 2 = j) with the sign of the correspondence. Along the
// face: same or opposite running direction of the two ranges; across it: leaving this zone enters the
// donor, so a max face meets a min face with +, two faces of the same kind with -.
std::array<int, 2> transform(const grid::FaceRange& r, const grid::FaceRange& d) {
  const int r_normal = is_i_face(r.face) ? 0 : 1, d_normal = is_i_face(d.face) ? 1 : 2;
  const int d_tangent = is_i_face(d.face) ? 2 : 1;
  const int normal_sign = is_max_face(r.face) != is_max_face(d.face) ? 1 : -1;
  const int tangent_sign = ((r.end >= r.begin) == (d.end >= d.begin)) ? 1 : -1;
  std::array<int, 2> t{};
  t[static_cast<std::size_t>(r_normal)] = normal_sign * d_normal;
  t[static_cast<std::size_t>(1 - r_normal)] = tangent_sign * d_tangent;
  return t;
}

}  // namespace

void write_cgns(const std::filesystem::path& file, const grid::MultiBlockGrid& g, const std::string& base) {
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    CgnsFile out(tmp);
    const int fn = out.id(), B = out.write_base(base, 2, 2);
    std::vector<int> zone(g.blocks.size());
    for (std::size_t k = 0; k < g.blocks.size(); ++k) {
      const grid::Block& b = g.blocks[k];
      cgsize_t size[6] = {b.ni + 1, b.nj + 1, b.ni, b.nj, 0, 0};
      cgns_check(cg_zone_write(fn, B, b.name.c_str(), size, CGNS_ENUMV(Structured), &zone[k]), "zone " + b.name);
      std::vector<double> x(b.nodes.size()), y(b.nodes.size());  // i fastest, as CGNS stores structured data
      for (std::size_t n = 0; n < b.nodes.size(); ++n) {
        x[n] = b.nodes[n].x();
        y[n] = b.nodes[n].y();
      }
      out.write_coordinate(B, zone[k], "CoordinateX", x);
      out.write_coordinate(B, zone[k], "CoordinateY", y);
    }
    for (const grid::BoundaryCondition& bc : g.boundaries) {
      const auto& b = g.blocks[static_cast<std::size_t>(bc.block)];
      const auto pr = point_range(b, bc.range);
      int BC = 0;
      cgns_check(cg_boco_write(fn, B, zone[static_cast<std::size_t>(bc.block)], bc.name.c_str(), bc_type(bc.kind),
                                 CGNS_ENUMV(PointRange), 2, pr.data(), &BC),
                 "boundary " + bc.name);
    }
    // Each interface from both sides; the reverse side of a periodic pair has the opposite translation.
    for (const grid::Connection& c : g.connections)
      for (int side = 0; side < 2; ++side) {
        const int zb = side == 0 ? c.block : c.donor, zd = side == 0 ? c.donor : c.block;
        const grid::FaceRange& r = side == 0 ? c.range : c.donor_range;
        const grid::FaceRange& d = side == 0 ? c.donor_range : c.range;
        const auto& blk = g.blocks[static_cast<std::size_t>(zb)];
        const auto& don = g.blocks[static_cast<std::size_t>(zd)];
        const auto pr = point_range(blk, r), pd = point_range(don, d);
        const auto t = transform(r, d);
        const std::string name = c.name + (side == 0 ? "" : "_donor");
        int I = 0;
        cgns_check(cg_1to1_write(fn, B, zone[static_cast<std::size_t>(zb)], name.c_str(), don.name.c_str(), pr.data(),
                                 pd.data(), t.data(), &I),
                   "connection " + name);
        if (c.periodic) {
          const float sign = side == 0 ? 1.0f : -1.0f;
          const float centre[2] = {0, 0}, angle[2] = {0, 0};
          const float shift[2] = {sign * static_cast<float>(c.translation.x()), sign * static_cast<float>(c.translation.y())};
          cgns_check(cg_1to1_periodic_write(fn, B, zone[static_cast<std::size_t>(zb)], I, centre, angle, shift),
                     "periodic " + name);
        }
      }
    out.close();
  });
}

}  // namespace cg::io
