// write_handoff: the selected files and only those, every file non-empty, no temporary left behind;
// format names round trip and unknown names are refused. CG_KEEP_OUTPUTS=DIR keeps the files of the
// full run in DIR for inspection.
#define BOOST_TEST_MODULE handoff_outputs
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <set>

#include "brep/temp_files.hpp"
#include "export/cooled_part.hpp"
#include "export/outputs.hpp"

namespace fs = std::filesystem;
using namespace cg;

BOOST_AUTO_TEST_CASE(format_names) {
  for (const auto& [name, f] : io::output_format_names()) {
    BOOST_TEST((io::parse_output_format(name) == f));
    BOOST_TEST(std::string(io::output_format_name(f)) == name);
  }
  BOOST_CHECK_THROW(io::parse_output_format("gltf"), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(all_and_selected_outputs) {
  test::CooledPartOptions o;
  o.holes = 3;
  const test::CooledPart p = test::cooled_example(o);
  io::HandoffOptions opt;
  opt.product_name = "hpt_rotor_cooled";
  test::TempDir dir("handoff");
  const char* keep = std::getenv("CG_KEEP_OUTPUTS");
  const fs::path out = keep ? fs::path(keep) : dir.path;
  fs::create_directories(out);
  const io::HandoffResult r = io::write_handoff(out, p.part, &p.model, opt);
  std::set<std::string> names;
  for (const auto& f : r.files) {
    names.insert(f.filename().string());
    BOOST_TEST(fs::file_size(f) > 100u, f);
  }
  std::set<std::string> expected{"blade.step", "blade.igs", "blade.brep", "blade.stl", "blade.vtm", "blade_blade.vtp",
                                 "blade_insert_1.vtp", "sections.svg"};
  if (r.notes.empty())
    expected.insert("preview.png");
  else
    BOOST_TEST_MESSAGE("note: " << r.notes.front());
  BOOST_TEST(names == expected);
  std::set<std::string> on_disk;
  for (const auto& e : fs::directory_iterator(out)) on_disk.insert(e.path().filename().string());
  if (!keep) BOOST_TEST(on_disk == expected);  // nothing else, no temporaries
  BOOST_TEST(r.summary.at("sections").size() == opt.section_spans.size());
  BOOST_TEST(r.summary.at("stl_triangles").get<int>() > 0);

  // Only STL and BREP.
  test::TempDir dir2("handoff_sel");
  opt.formats = {io::OutputFormat::Stl, io::OutputFormat::Brep};
  const io::HandoffResult r2 = io::write_handoff(dir2.path, p.part, &p.model, opt);
  BOOST_TEST(dir2.entries().size() == 2u);
  BOOST_TEST(r2.files.size() == 2u);
}
