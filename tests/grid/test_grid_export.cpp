// Grid files (export/grid_*): the C3X cascade grid written as CGNS, VTK (.vtm + .vts) and Plot3D and read
// back — the CGNS file with the CGNS library itself (zones, sizes, coordinates bit-exact, boundary
// conditions with types and ranges, 1-to-1 connections with transforms, periodic translations), the VTK
// files with VTK's XML reader (dimensions and points bit-exact), the Plot3D file by parsing (17 significant
// digits: exact). The grid job end to end on the config path (grid section parsed, report written) and its
// errors.
#define BOOST_TEST_MODULE grid_export
#include <boost/test/unit_test.hpp>

#include <cgnslib.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridReader.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "../brep/temp_files.hpp"
#include "export/grid_cgns.hpp"
#include "export/grid_plot3d.hpp"
#include "export/grid_vtk.hpp"
#include "grid_fixtures.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/grid_job.hpp"

using namespace cg;

namespace {

const grid::SectionGrid& cascade() {
  static const grid::SectionGrid g = [] {
    grid::SectionGridOptions o;
    o.cascade = grid::CascadeOptions{};
    o.cascade->pitch = grid::test::kC3xPitch;
    return grid::build_section_grid(grid::test::c3x_section(), o);
  }();
  return g;
}

}  // namespace

BOOST_AUTO_TEST_CASE(cgns_reads_back) {
  const test::TempDir dir("grid_cgns");
  const grid::MultiBlockGrid& g = cascade().grid;
  const auto file = dir.path / "c3x.cgns";
  io::write_cgns(file, g, "c3x_section");
  int fn = 0;
  BOOST_REQUIRE(cg_open(file.c_str(), CG_MODE_READ, &fn) == CG_OK);
  int nbases = 0;
  cg_nbases(fn, &nbases);
  BOOST_TEST(nbases == 1);
  char name[33];
  int cell_dim = 0, phys_dim = 0;
  cg_base_read(fn, 1, name, &cell_dim, &phys_dim);
  BOOST_TEST(std::string(name) == "c3x_section");
  BOOST_TEST(cell_dim == 2);
  BOOST_TEST(phys_dim == 2);
  CGNS_ENUMT(MassUnits_t) mu;
  CGNS_ENUMT(LengthUnits_t) lu;
  CGNS_ENUMT(TimeUnits_t) tu;
  CGNS_ENUMT(TemperatureUnits_t) ku;
  CGNS_ENUMT(AngleUnits_t) au;
  cg_goto(fn, 1, "end");
  BOOST_TEST(cg_units_read(&mu, &lu, &tu, &ku, &au) == CG_OK);
  BOOST_TEST(lu == CGNS_ENUMV(Millimeter));
  int nzones = 0;
  cg_nzones(fn, 1, &nzones);
  BOOST_TEST(nzones == 3);
  std::map<std::string, int> bc_types;
  int n1to1_total = 0, periodic_total = 0;
  for (int z = 1; z <= nzones; ++z) {
    // The CGNS library lists zones sorted by name: find the block by its name.
    cgsize_t size[6];
    cg_zone_read(fn, 1, z, name, size);
    const auto it = std::find_if(g.blocks.begin(), g.blocks.end(), [&](const grid::Block& x) { return x.name == name; });
    BOOST_REQUIRE(it != g.blocks.end());
    const grid::Block& b = *it;
    BOOST_TEST(size[0] == b.ni + 1);
    BOOST_TEST(size[1] == b.nj + 1);
    BOOST_TEST(size[2] == b.ni);
    BOOST_TEST(size[3] == b.nj);
    std::vector<double> x(b.nodes.size()), y(b.nodes.size());
    cgsize_t lo[2] = {1, 1}, hi[2] = {b.ni + 1, b.nj + 1};
    BOOST_REQUIRE(cg_coord_read(fn, 1, z, "CoordinateX", CGNS_ENUMV(RealDouble), lo, hi, x.data()) == CG_OK);
    BOOST_REQUIRE(cg_coord_read(fn, 1, z, "CoordinateY", CGNS_ENUMV(RealDouble), lo, hi, y.data()) == CG_OK);
    bool same = true;
    for (std::size_t k = 0; k < b.nodes.size(); ++k) same = same && x[k] == b.nodes[k].x() && y[k] == b.nodes[k].y();
    BOOST_TEST(same);
    int nbocos = 0;
    cg_nbocos(fn, 1, z, &nbocos);
    for (int bc = 1; bc <= nbocos; ++bc) {
      CGNS_ENUMT(BCType_t) type;
      CGNS_ENUMT(PointSetType_t) pset;
      cgsize_t npnts, nlist;
      int nidx[2], ndata;
      CGNS_ENUMT(DataType_t) dtype;
      cg_boco_info(fn, 1, z, bc, name, &type, &pset, &npnts, nidx, &nlist, &dtype, &ndata);
      bc_types[name] = static_cast<int>(type);
      BOOST_TEST(pset == CGNS_ENUMV(PointRange));
      cgsize_t pr[4];
      cg_boco_read(fn, 1, z, bc, pr, nullptr);
      if (std::string(name) == "wall") {  // the whole j = 1 row of the O-grid
        BOOST_TEST(b.name == "o_grid");
        BOOST_TEST(pr[1] == 1);
        BOOST_TEST(pr[3] == 1);
        BOOST_TEST(std::abs(pr[2] - pr[0]) == b.ni);
      }
    }
    int n1to1 = 0;
    cg_n1to1(fn, 1, z, &n1to1);
    n1to1_total += n1to1;
    for (int c = 1; c <= n1to1; ++c) {
      char donor[33];
      cgsize_t range[4], donor_range[4];
      int transform[2];
      BOOST_REQUIRE(cg_1to1_read(fn, 1, z, c, name, donor, range, donor_range, transform) == CG_OK);
      BOOST_TEST(std::abs(transform[0]) + std::abs(transform[1]) == 3);
      float centre[2], angle[2], shift[2] = {0, 0};
      if (cg_1to1_periodic_read(fn, 1, z, c, centre, angle, shift) == CG_OK) {
        ++periodic_total;
        BOOST_TEST(std::abs(std::abs(shift[1]) - grid::test::kC3xPitch) < 1e-4);
        BOOST_TEST(shift[0] == 0.0f);
      }
      // The transform maps every node of the range onto its donor node (CGNS SIDS: donor index =
      // T (index - begin) + donor begin), where the coordinates agree up to the periodic translation
      // (stored in single precision).
      const auto dit = std::find_if(g.blocks.begin(), g.blocks.end(), [&](const grid::Block& x) { return x.name == donor; });
      BOOST_REQUIRE(dit != g.blocks.end());
      const int along = range[0] != range[2] ? 0 : 1;
      const cgsize_t n = std::abs(range[along + 2] - range[along]);
      const int step = range[along + 2] >= range[along] ? 1 : -1;
      double worst = 0;
      for (cgsize_t k = 0; k <= n; ++k) {
        cgsize_t idx[2] = {range[0], range[1]};
        idx[along] += step * k;
        cgsize_t didx[2];
        for (int a = 0; a < 2; ++a) {
          const int t = transform[a], axis = std::abs(t) - 1;
          didx[axis] = donor_range[axis] + (t > 0 ? 1 : -1) * (idx[a] - range[a]);
        }
        const Eigen::Vector2d p = b.at(static_cast<int>(idx[0]) - 1, static_cast<int>(idx[1]) - 1);
        const Eigen::Vector2d q = dit->at(static_cast<int>(didx[0]) - 1, static_cast<int>(didx[1]) - 1);
        worst = std::max(worst, (p + Eigen::Vector2d(shift[0], shift[1]) - q).norm());
      }
      BOOST_TEST(worst < 1e-5, name << " -> " << donor << ": " << worst);
    }
  }
  cg_close(fn);
  BOOST_TEST(bc_types["wall"] == static_cast<int>(CGNS_ENUMV(BCWall)));
  BOOST_TEST(bc_types["inlet"] == static_cast<int>(CGNS_ENUMV(BCInflow)));
  BOOST_TEST(bc_types["outlet"] == static_cast<int>(CGNS_ENUMV(BCOutflow)));
  BOOST_TEST(n1to1_total == 2 * static_cast<int>(g.connections.size()));  // both sides of every interface
  BOOST_TEST(periodic_total == 6);  // three periodic pairs, both sides
}

BOOST_AUTO_TEST_CASE(vtk_and_plot3d_read_back) {
  const test::TempDir dir("grid_vtk");
  const grid::MultiBlockGrid& g = cascade().grid;
  const auto files = io::write_vtm(dir.path / "c3x.vtm", g);
  BOOST_TEST(files.size() == 4u);
  const std::string vtm = test::read_text(dir.path / "c3x.vtm");
  BOOST_TEST(vtm.find("file=\"c3x_inlet.vts\"") != std::string::npos);
  for (std::size_t k = 0; k < g.blocks.size(); ++k) {
    const grid::Block& b = g.blocks[k];
    vtkNew<vtkXMLStructuredGridReader> r;
    r->SetFileName((dir.path / ("c3x_" + b.name + ".vts")).c_str());
    r->Update();
    vtkStructuredGrid* sg = r->GetOutput();
    int dims[3];
    sg->GetDimensions(dims);
    BOOST_TEST(dims[0] == b.ni + 1);
    BOOST_TEST(dims[1] == b.nj + 1);
    BOOST_TEST(dims[2] == 1);
    bool same = true;
    for (std::size_t n = 0; n < b.nodes.size(); ++n) {
      double p[3];
      sg->GetPoint(static_cast<vtkIdType>(n), p);
      same = same && p[0] == b.nodes[n].x() && p[1] == b.nodes[n].y() && p[2] == 0.0;
    }
    BOOST_TEST(same);
    BOOST_TEST(sg->GetCellData()->GetArray("scaled_jacobian") != nullptr);
  }
  io::write_plot3d(dir.path / "c3x.xyz", g);
  std::ifstream in(dir.path / "c3x.xyz");
  int nb = 0;
  in >> nb;
  BOOST_TEST(nb == 3);
  std::vector<std::array<int, 3>> dims(static_cast<std::size_t>(nb));
  for (auto& d : dims) in >> d[0] >> d[1] >> d[2];
  bool same = true;
  for (int k = 0; k < nb; ++k) {
    const grid::Block& b = g.blocks[static_cast<std::size_t>(k)];
    BOOST_TEST(dims[static_cast<std::size_t>(k)][0] == b.ni + 1);
    BOOST_TEST(dims[static_cast<std::size_t>(k)][2] == 1);
    for (int c = 0; c < 3; ++c)
      for (const auto& p : b.nodes) {
        double v;
        in >> v;
        same = same && v == (c < 2 ? p[c] : 0.0);
      }
  }
  BOOST_TEST(same);
  BOOST_TEST(static_cast<bool>(in));
}

BOOST_AUTO_TEST_CASE(grid_job_on_the_c3x_example) {
  // data/examples/c3x_vane.json with a grid section, as `coolinggen grid` runs it.
  nlohmann::json doc = nlohmann::json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  doc["grid"] = {{"cells_around", 175}, {"first_cell_height", 0.01}, {"cascade", {{"pitch", 117.73}}}};
  const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "c3x");
  BOOST_TEST(c.grid.given);
  BOOST_TEST(c.grid.options.cascade.has_value());
  const pipeline::GridResult r = pipeline::run_grid(c);
  BOOST_TEST(r.runs.size() == 1u);  // one defined section (the model repeats it at the casing)
  const test::TempDir dir("grid_job");
  const auto out = dir.path / "out";
  // A file of an earlier grid run that this run does not write is removed (the index lists it).
  std::filesystem::create_directories(out);
  {
    std::ofstream(out / "section_7.xyz") << "old";
    std::ofstream(out / "grid_report.json") << R"({"generator": "coolinggen", "outputs": ["section_7.xyz", "grid_report.json"]})";
  }
  const pipeline::WrittenGrid w = pipeline::write_grid_outputs(c, r, out);
  BOOST_TEST(w.files.back() == "grid_report.json");
  BOOST_TEST(!std::filesystem::exists(out / "section_7.xyz"));
  for (const char* f : {"section_0.vtm", "section_0_o_grid.vts", "section_0_inlet.vts", "section_0_outlet.vts",
                        "section_0.xyz", "section_0.cgns", "grid_report.json"})
    BOOST_TEST(std::filesystem::exists(out / f), f);
  const nlohmann::json rep = nlohmann::json::parse(test::read_text(out / "grid_report.json"));
  const auto& s = rep["sections"][0];
  BOOST_TEST(s["cells"].get<int>() == 12806);
  BOOST_TEST(s["inverted_cells"].get<int>() == 0);
  BOOST_TEST(s["wall"]["max_angle_deviation_deg"].get<double>() < 1e-6);
  BOOST_TEST(std::abs(s["wall"]["first_cell_height_mm"]["min"].get<double>() - 0.01) < 1e-11);
  BOOST_TEST(s["files"].size() == 6u);
  BOOST_TEST(rep["model"]["name"].get<std::string>() == "c3x_vane");
  BOOST_TEST(rep["outputs"].size() == 7u);
}

BOOST_AUTO_TEST_CASE(grid_config_errors_name_the_field) {
  nlohmann::json doc = nlohmann::json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  auto message = [&](const nlohmann::json& grid) {
    nlohmann::json d = doc;
    d["grid"] = grid;
    try {
      config::parse_config(d, COOLINGGEN_SOURCE_DIR "/data/examples", "c3x");
    } catch (const config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message({{"growth_ratio", 1.0}}).rfind("grid.growth_ratio:", 0) == 0);
  BOOST_TEST(message({{"sections", {1}}}).rfind("grid.sections[0]:", 0) == 0);  // one section only
  BOOST_TEST(message({{"cascade", {{"pitch", -1}}}}).rfind("grid.cascade.pitch:", 0) == 0);
  BOOST_TEST(message({{"cascade", {{"pitch", 100}, {"inlet_cells", {19, 31}}}}}).rfind("grid.cells_around:", 0) == 0);
  BOOST_TEST(message({{"cells", 3}}).rfind("grid.cells:", 0) == 0);  // unknown key
  BOOST_TEST(message({{"first_cell_height", 0}}).rfind("grid.first_cell_height:", 0) == 0);
  // Options only the section can judge come from the job, prefixed the same way.
  nlohmann::json d = doc;
  d["grid"] = {{"thickness", 100}};
  const config::Config c = config::parse_config(d, COOLINGGEN_SOURCE_DIR "/data/examples", "c3x");
  try {
    pipeline::run_grid(c);
    BOOST_FAIL("no error");
  } catch (const config::ConfigError& e) {
    BOOST_TEST(std::string(e.what()).rfind("grid.thickness:", 0) == 0);
    BOOST_TEST(std::string(e.what()).find("(sections[0])") != std::string::npos);
  }
}
