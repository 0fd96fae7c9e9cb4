// The coordinate range of docs/formats.md: at ±1e10 every intersector still answers correctly
// (float products of edges and offsets stay finite), and input beyond it — a vertex, a ray
// origin, a transformed object, a visibility vertex or origin — or a direction whose largest
// component is outside [1e-6, 1e16] is refused at load time (exit 2, file:line) instead of
// giving a silent miss.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace rayvec {
namespace {

const std::string kBigTriangle = "v -1e10 -1e10 1e10\nv 1e10 -1e10 1e10\nv 0 1e10 1e10\nf 1 2 3\n";

// The hit column `tri` of each output row of `hits`.
std::vector<std::string> hit_ids(const std::string& csv) {
  std::vector<std::string> ids;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line))
    ids.push_back(line.substr(line.find(',') + 1, line.find(',', line.find(',') + 1) - line.find(',') - 1));
  return ids;
}

TEST(CoordinateRange, EveryIntersectorHitsATriangleAtTheBound) {
  const std::string dir = test::temp_dir("range_bound");
  test::write_file(dir + "/m.obj", kBigTriangle);
  // Straight on from -1e10 with a unit, a 1e-6 and a 1e16 direction; then from the far corner of
  // the range towards the centroid with a direction whose largest component is 1e-6.
  test::write_file(dir + "/r.csv",
                   "0,-3e9,-1e10,0,0,1\n0,-3e9,-1e10,0,0,1e-6\n0,-3e9,-1e10,0,0,1e16\n"
                   "-1e10,-1e10,-1e10,5e-7,3.3333333e-7,1e-6\n");
  for (const std::string isa : {"scalar", "auto"})
    for (const std::string intersector : {"mt", "mt64", "watertight", "watertight64", "paper"}) {
      const auto r = test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv --isa " + isa +
                                   " --intersector " + intersector);
      ASSERT_EQ(r.status, 0) << r.err;
      const auto ids = hit_ids(r.out);
      ASSERT_EQ(ids.size(), 4u) << r.out;
      for (std::size_t i = 0; i < ids.size(); ++i)
        EXPECT_EQ(ids[i], "0") << isa << " " << intersector << " ray " << i << "\n" << r.out;
    }
}

// Runs `hits` on the two texts; expects exit 2 with `message` and no output.
void expect_hits_refuses(const std::string& obj, const std::string& rays, const std::string& message) {
  const std::string dir = test::temp_dir("range_refuse");
  test::write_file(dir + "/m.obj", obj);
  test::write_file(dir + "/r.csv", rays);
  const auto r =
      test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv -o " + dir + "/out.csv");
  EXPECT_EQ(r.status, 2) << message << ": " << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "expected '" << message << "' in: " << r.err;
  EXPECT_FALSE(std::ifstream(dir + "/out.csv").good());
}

TEST(CoordinateRange, VerticesRayOriginsAndDirectionsBeyondItAreRefused) {
  const std::string ray = "0,0,0,0,0,1\n";
  expect_hits_refuses("v -1e19 -1e19 1\nv 1e19 -1e19 1\nv 0 1e19 1\nf 1 2 3\n", ray,
                      "m.obj:1: `v` coordinate 1 '-1e19' is beyond ±1e10");
  expect_hits_refuses(kBigTriangle + "v 0 0 1.1e10\n", ray,
                      "m.obj:5: `v` coordinate 3 '1.1e10' is beyond ±1e10");
  expect_hits_refuses(kBigTriangle, "0,0,0,0,0,3e38\n",
                      "r.csv:1: direction (0, 0, 3.00000001e+38) is too long");
  expect_hits_refuses(kBigTriangle, "0,0,0,1e-7,0,0\n",
                      "r.csv:1: direction (1.00000001e-07, 0, 0) is too short");
  expect_hits_refuses(kBigTriangle, "0,2e10,0,0,0,1\n",
                      "r.csv:1: origin coordinate oy = 2e+10 is beyond ±1e10");
}

TEST(CoordinateRange, TransformedObjectsAndVisibilityInputsBeyondItAreRefused) {
  const std::string dir = test::temp_dir("range_scene");
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  test::write_file(dir + "/s.json",
                   "{\"objects\": [\n  {\"obj\": \"m.obj\",\n   \"transform\": {\"scale\": 1e12}}]}\n");
  auto r = test::run_cli("render -q " + dir + "/s.json -o " + dir + "/out.png");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("s.json:3: objects[0].transform: moves a vertex of"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("beyond ±1e10"), std::string::npos) << r.err;
  test::write_file(dir + "/v.csv", "0,0,1\n1e19,0,1\n0,1,1\n");
  test::write_file(dir + "/f.csv", "0,1,2\n");
  r = test::run_cli("visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv -o " + dir + "/out.txt");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(dir + "/v.csv:2: coordinate 1 (9.99999998e+18) is beyond ±1e10"), std::string::npos)
      << r.err;
  test::write_file(dir + "/v.csv", "0,0,1\n1,0,1\n0,1,1\n");
  r = test::run_cli("visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv --origin 0,0,-1e11");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--origin: '0,0,-1e11' is beyond ±1e10"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rayvec
