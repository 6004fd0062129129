// Wall-orthogonal grids around blade sections (src/grid): the exact wall patches and the two layouts,
// on the C3X vane section and the HPT rotor's mid section.
// Checks (tolerances): no inverted cell (every corner Jacobian > 0); wall angle deviation of the first grid
// line from 90 deg < 1e-6 deg (measured ~1e-10 deg: rounding of node differences of ~1e-2 mm cells) and of
// the patches' own derivatives < 1e-9 deg; first cell height equal to the configured one to 1e-9
// relative (nodes placed by the closed form of the normal lines); cell counts; node-matched interfaces and
// periodic pairs to 1e-9 mm.
#define BOOST_TEST_MODULE section_grids
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "grid_fixtures.hpp"
#include "src/core/error.hpp"
#include "src/grid/section_grid.hpp"
#include "src/grid/wall_patches.hpp"

using namespace cg;
using namespace cg::grid;

namespace {

void check_grid(const SectionGrid& g, double h1) {
  const SectionGridReport& r = g.report;
  BOOST_TEST(r.inverted_cells == 0);
  BOOST_TEST(r.min_scaled_jacobian > 0.0);
  for (const Block& b : g.grid.blocks) BOOST_TEST(block_quality(b).inverted_cells == 0);
  BOOST_TEST(r.wall.max_angle_deviation_deg < 1e-6);
  BOOST_TEST(r.patch_wall_angle_deviation_deg < 1e-9);
  BOOST_TEST(std::abs(r.wall.min_first_cell_height / h1 - 1) < 1e-9);
  BOOST_TEST(std::abs(r.wall.max_first_cell_height / h1 - 1) < 1e-9);
  BOOST_TEST(r.max_connection_mismatch < 1e-9);
  for (const Connection& c : g.grid.connections) BOOST_TEST(connection_mismatch(g.grid, c) < 1e-9);
}

}  // namespace

BOOST_AUTO_TEST_CASE(wall_patches_agree_at_joints_and_are_orthogonal) {
  const blade::SectionProfile& s = test::c3x_section();
  const WallPatches p(s.curve, 2.0);
  BOOST_TEST(p.size() == static_cast<int>(p.breaks().size()) - 1);
  BOOST_TEST(p.max_degree() == 4);  // cubic polynomial segments: z~ = D x_u (degree 2), L quadratic
  BOOST_TEST(p.outer_side() == 1.0);  // the C3X profile runs clockwise: outside on the left
  BOOST_TEST(p.max_wall_angle_deviation_deg() < 1e-9);
  const double size = 150;
  for (int k = 0; k < p.size(); ++k) {
    const auto& a = p.patch(k).patch;
    const auto& b = p.patch((k + 1) % p.size()).patch;
    for (double v : {0.0, 0.3, 1.0}) BOOST_TEST((a.point(1.0, v) - b.point(0.0, v)).norm() < 1e-12 * size);
  }
  // Nodes: on the normal line through the wall point, at the requested distance.
  for (double u : {0.0, 0.123, 0.5, 0.77}) {
    Eigen::Vector2d d[2];
    s.curve.derivatives(u, 1, d);
    for (double dist : {0.01, 0.7, 2.0}) {
      const Eigen::Vector2d q = p.point(u, dist) - d[0];
      BOOST_TEST(std::abs(q.norm() - dist) < 1e-12 * size);
      BOOST_TEST(std::abs(q.dot(d[1].normalized())) < 1e-12 * size);
      BOOST_TEST(q.dot(p.outer_normal(u)) > 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(o_grid_around_c3x) {
  SectionGridOptions o;
  o.first_cell_height = 0.02;
  o.thickness = 8.0;
  const SectionGrid g = build_section_grid(test::c3x_section(), o);
  BOOST_TEST(g.grid.blocks.size() == 1u);
  BOOST_TEST(g.grid.blocks[0].ni == 175);
  BOOST_TEST(g.grid.blocks[0].nj == 59);
  BOOST_TEST(g.report.cells == 175 * 59);
  BOOST_TEST(g.report.wall_layers == 59);  // every layer on the exact normal lines
  check_grid(g, 0.02);
  // The outer row is at the thickness everywhere.
  const Block& b = g.grid.blocks[0];
  for (int i = 0; i < b.ni; i += 7) BOOST_TEST(std::abs((b.at(i, b.nj) - b.at(i, 0)).norm() - 8.0) < 1e-9);
}

BOOST_AUTO_TEST_CASE(o_grid_around_rotor_with_defaults) {
  const SectionGrid g = build_section_grid(test::rotor_section(), SectionGridOptions{});
  check_grid(g, 2e-4 * 38);
  BOOST_TEST(std::abs(g.report.thickness - 0.1 * 38) < 1e-12);
}

BOOST_AUTO_TEST_CASE(c3x_cascade_like_the_paper) {
  // Lang & Schroecker Fig. 6: periodic O-grid 175 x 59, inlet 19 x 30, outlet 39 x 49: 12 806 cells.
  SectionGridOptions o;
  o.cascade = CascadeOptions{};
  o.cascade->pitch = test::kC3xPitch;
  const SectionGrid g = build_section_grid(test::c3x_section(), o);
  BOOST_TEST(g.grid.blocks.size() == 3u);
  BOOST_TEST(g.report.cells == 12806);
  BOOST_TEST(g.grid.blocks[1].ni == 19);
  BOOST_TEST(g.grid.blocks[1].nj == 30);
  BOOST_TEST(g.grid.blocks[2].ni == 39);
  BOOST_TEST(g.grid.blocks[2].nj == 49);
  check_grid(g, g.report.first_cell_height);
  int periodic = 0;
  for (const Connection& c : g.grid.connections)
    if (c.periodic) {
      ++periodic;
      BOOST_TEST((c.translation - Eigen::Vector2d(0, test::kC3xPitch)).norm() < 1e-12);
    }
  BOOST_TEST(periodic == 3);  // O-grid, inlet and outlet blocks
  BOOST_TEST(g.grid.boundaries.size() == 3u);  // wall, inlet, outlet
}

BOOST_AUTO_TEST_CASE(rotor_cascade_other_counts) {
  SectionGridOptions o;
  o.cells_around = 241;
  o.cells_normal = 40;
  o.first_cell_height = 0.005;
  o.cascade = CascadeOptions{};
  o.cascade->pitch = test::kRotorPitch;
  o.cascade->inlet_cells_pitchwise = 40;
  o.cascade->outlet_cells_pitchwise = 61;
  const SectionGrid g = build_section_grid(test::rotor_section(), o);
  BOOST_TEST(g.report.cells == 241 * 40 + 19 * 40 + 39 * 61);
  check_grid(g, 0.005);
}

namespace {

std::string error_of(const blade::SectionProfile& s, const SectionGridOptions& o) {
  try {
    build_section_grid(s, o);
  } catch (const InvalidGeometry& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(impossible_options_name_the_option) {
  const blade::SectionProfile& s = test::c3x_section();
  SectionGridOptions o;
  o.thickness = 90;  // past the centre of curvature of the concave pressure side (radius 94.5 mm)
  BOOST_TEST(error_of(s, o).find("centre of curvature") != std::string::npos);
  o = SectionGridOptions{};
  o.cells_normal = 5;
  o.thickness = 10;  // 5 cells from 0.029 mm growing by 1.15 reach 0.2 mm only
  BOOST_TEST(error_of(s, o).find("cannot be reached") != std::string::npos);
  o = SectionGridOptions{};
  o.growth_ratio = 1.0;
  BOOST_TEST(error_of(s, o).rfind("growth_ratio:", 0) == 0);
  o = SectionGridOptions{};
  o.cascade = CascadeOptions{};
  o.cascade->pitch = 60;  // narrower than the staggered vane across its mid-line
  BOOST_TEST(error_of(s, o).rfind("cascade.pitch:", 0) == 0);
  o.cascade->pitch = test::kC3xPitch;
  o.cascade->outlet_cells_pitchwise = 48;  // 175 - 30 - 48 is odd
  BOOST_TEST(error_of(s, o).rfind("cells_around:", 0) == 0);
  o.cascade->outlet_cells_pitchwise = 49;
  o.cascade->inlet_distance = 5;  // the O-grid reaches further upstream
  BOOST_TEST(error_of(s, o).rfind("cascade.inlet_distance:", 0) == 0);
}
