// `rayvec visibility` end to end on the hand-checked files, plus its errors.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace rayvec {
namespace {

const std::string kData = RAYVEC_TEST_DATA;

TEST(VisibilityCli, HandCheckedFilesGiveTheExpectedLines) {
  const std::string dir = test::temp_dir("vis_cli");
  const auto r = test::run_cli("visibility --verts " + kData + "/visibility/verts.csv --faces " + kData +
                               "/visibility/meshes.csv -o " + dir + "/out.txt");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_file(dir + "/out.txt"), test::read_file(kData + "/visibility/expected.txt"));
  // One warning for the dropped face, counted.
  EXPECT_NE(r.err.find("warning: " + kData + "/visibility/meshes.csv: 1 of 3 faces dropped"),
            std::string::npos)
      << r.err;
}

TEST(VisibilityCli, OriginMovesTheEye) {
  // From behind the far vertices (z = 3) every vertex at z = 2 is in front of the triangle at z = 1.
  const auto r = test::run_cli("visibility --origin 0,0,3 --isa scalar --verts " + kData +
                               "/visibility/verts.csv --faces " + kData + "/visibility/meshes.csv");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "1\n1\n1\n1\n0\nnan\n1\n1\n1\n1\n");
}

TEST(VisibilityCli, BadInputsExitTwoNamingFileAndLine) {
  const std::string dir = test::temp_dir("vis_bad");
  test::write_file(dir + "/v.csv", "0,0,1\n1,0,1\n0,1,1\n");
  test::write_file(dir + "/f.csv", "0,1,2\n0,1,3\n");
  auto r =
      test::run_cli("visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv -o " + dir + "/o.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/f.csv:2: field 3 (3) is out of range"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/o.txt"));
  test::write_file(dir + "/f.csv", "0,1,2.5\n");
  r = test::run_cli("visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/f.csv:1: field 3 (2.5) is not an integer"), std::string::npos) << r.err;
  r = test::run_cli("visibility --origin 1,2 --verts " + dir + "/v.csv --faces " + dir + "/f.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--origin: '1,2'"), std::string::npos) << r.err;
  r = test::run_cli("visibility --origin 0,nan,0 --verts " + dir + "/v.csv --faces " + dir + "/f.csv");
  EXPECT_EQ(r.status, 2);
  r = test::run_cli("visibility --verts " + dir + "/none.csv --faces " + dir + "/f.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/none.csv: cannot read"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rayvec
