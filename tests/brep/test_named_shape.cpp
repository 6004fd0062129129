#define BOOST_TEST_MODULE named_shape
#include <boost/test/unit_test.hpp>

#include "src/brep/named_shape.hpp"

using cg::brep::feature_kind;

BOOST_AUTO_TEST_CASE(kind_is_the_words_before_the_first_number) {
  BOOST_TEST(feature_kind("film_row_2_hole_014") == "film_row");
  BOOST_TEST(feature_kind("showerhead_1_hole_003") == "showerhead");
  BOOST_TEST(feature_kind("chamber_2_wall") == "chamber");
  BOOST_TEST(feature_kind("turbulator_3_012") == "turbulator");
  BOOST_TEST(feature_kind("te_slot_07") == "te_slot");
  BOOST_TEST(feature_kind("blade_wall") == "blade_wall");
  BOOST_TEST(feature_kind("hub") == "hub");
  BOOST_TEST(feature_kind("insert_1") == "insert");
  BOOST_TEST(feature_kind("7") == "7");  // no word before the number: the name itself
}
