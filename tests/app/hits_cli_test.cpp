// `rayvec hits` end to end: the CLI's output parsed back equals the library's answers exactly, and
// every input error exits 2 (1 for an unwritable output) naming file:line, leaving no output file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>

#include "accel/accelerator.h"
#include "io/rays_csv.h"
#include "scene/obj_loader.h"
#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  std::string dir, obj, rays;
};

// 200 random triangles in the unit cube and 500 rays through it, written with %.9g.
Fixture write_random_inputs(const std::string& name) {
  Fixture f{test::temp_dir(name), "", ""};
  f.obj = f.dir + "/mesh.obj";
  f.rays = f.dir + "/rays.csv";
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), d(-1.0f, 1.0f);
  std::string obj, rays = "# origin, direction, [tmin, tmax]\n";
  char line[256];
  for (int t = 0; t < 200; ++t) {
    const Vec3f c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", c.x + 0.2f * d(rng), c.y + 0.2f * d(rng),
                    c.z + 0.2f * d(rng));
      obj += line;
    }
    std::snprintf(line, sizeof line, "f %d %d %d\n", 3 * t + 1, 3 * t + 2, 3 * t + 3);
    obj += line;
  }
  for (int r = 0; r < 500; ++r) {
    const Vec3f o{u(rng) * 3 - 1, u(rng) * 3 - 1, -1.5f};
    const Vec3f target{u(rng), u(rng), u(rng)};
    const Vec3f dir = target - o;
    if (r % 3 == 0)
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", o.x, o.y, o.z, dir.x,
                    dir.y, dir.z, 0.1f * u(rng), 0.5f + u(rng));
    else
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", o.x, o.y, o.z, dir.x, dir.y, dir.z);
    rays += line;
  }
  test::write_file(f.obj, obj);
  test::write_file(f.rays, rays);
  return f;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

float to_float(const std::string& s) { return std::strtof(s.c_str(), nullptr); }

TEST(HitsCli, ClosestHitsReadBackToTheLibraryResults) {
  const Fixture f = write_random_inputs("hits_roundtrip");
  const auto r = test::run_cli("hits --mesh " + f.obj + " --rays " + f.rays + " --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("500 rays"), std::string::npos) << r.err;

  const ObjModel model = load_obj(f.obj);
  const RayBatch rays = read_rays_csv(f.rays);
  const auto accel = make_accelerator(AccelKind::brute, model.mesh, TraceConfig{best_isa(), Intersector::mt});
  std::vector<Hit> hits(rays.size());
  trace_closest(*accel, rays, hits);

  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), rays.size() + 1);
  EXPECT_EQ(lines[0], "ray,tri,t,u,v");
  int hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    int ray = -2, tri = -2;
    char t[64], uu[64], vv[64];
    ASSERT_EQ(std::sscanf(lines[i + 1].c_str(), "%d,%d,%63[^,],%63[^,],%63s", &ray, &tri, t, uu, vv), 5)
        << lines[i + 1];
    EXPECT_EQ(ray, static_cast<int>(i));
    EXPECT_EQ(tri, hits[i].tri) << "ray " << i;
    EXPECT_EQ(to_float(t), hits[i].t) << lines[i + 1];  // bit-exact: printed to read back exactly
    if (hits[i].hit()) {
      ++hit_count;
      EXPECT_EQ(to_float(uu), hits[i].u);
      EXPECT_EQ(to_float(vv), hits[i].v);
    } else {
      EXPECT_EQ(std::string(t), "inf");
      EXPECT_EQ(std::string(uu), "0");
    }
  }
  EXPECT_GT(hit_count, 50);  // the scene is hit often enough for the comparison to mean something
  EXPECT_LT(hit_count, 500);
}

TEST(HitsCli, AnyHitMatchesTheLibraryAndWritesTheFileAtomically) {
  const Fixture f = write_random_inputs("hits_any");
  const std::string out = f.dir + "/any.csv";
  const auto r =
      test::run_cli("hits --any --isa scalar --mesh " + f.obj + " --rays " + f.rays + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const ObjModel model = load_obj(f.obj);
  const RayBatch rays = read_rays_csv(f.rays);
  const auto accel =
      make_accelerator(AccelKind::brute, model.mesh, TraceConfig{Isa::scalar, Intersector::mt});
  const auto lines = lines_of(test::read_file(out));
  ASSERT_EQ(lines.size(), rays.size() + 1);
  EXPECT_EQ(lines[0], "ray,hit");
  for (std::size_t i = 0; i < rays.size(); ++i)
    EXPECT_EQ(lines[i + 1], std::to_string(i) + "," + (accel->occluded(rays[i]) ? "1" : "0"));
  for (const auto& entry : fs::directory_iterator(f.dir))  // no temporary left behind
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
}

// Runs `hits` on a bad input; checks exit status, the message, and that no output appeared.
void expect_failure(const std::string& name, const std::string& obj_text, const std::string& rays_text,
                    int status, const std::string& message, const std::string& out_path = "") {
  const std::string dir = test::temp_dir(name);
  test::write_file(dir + "/m.obj", obj_text);
  test::write_file(dir + "/r.csv", rays_text);
  const std::string out = out_path.empty() ? dir + "/hits.csv" : out_path;
  const auto r = test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv -o " + out);
  EXPECT_EQ(r.status, status) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(r.out, "");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2) << "an output or temporary file was left in " << dir;
}

const std::string kTri = "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n";

TEST(HitsCli, EveryInputErrorNamesFileAndLine) {
  expect_failure("hits_e5", kTri, "0,0,0,0,0,1\n0,0,0,0,0\n", 2, "r.csv:2: found 5 fields, expected 6");
  expect_failure("hits_enum", kTri, "0,0,0,0,0,1\n\n0,0,zero,0,0,1\n", 2,
                 "r.csv:3: field 3 'zero' is not a number");
  expect_failure("hits_enan", kTri, "nan,0,0,0,0,1\n", 2, "r.csv:1: origin must be finite, but ox is nan");
  expect_failure("hits_edir", kTri, "0,0,0,0,0,0\n", 2, "r.csv:1: direction is zero");
  expect_failure("hits_eobj", kTri + "f 1 2 4\n", "0,0,0,0,0,1\n", 2,
                 "m.obj:5: face vertex index 4 is out of range");
  expect_failure("hits_eobjnan", "v 0 0 nan\nv 1 0 1\nv 0 1 1\nf 1 2 3\n", "0,0,0,0,0,1\n", 2,
                 "m.obj:1: `v` coordinate 3 'nan' is not a finite number");
}

TEST(HitsCli, MissingFilesAreInputErrors) {
  const std::string dir = test::temp_dir("hits_missing");
  test::write_file(dir + "/m.obj", kTri);
  auto r = test::run_cli("hits --mesh " + dir + "/nope.obj --rays " + dir + "/m.obj");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/nope.obj: cannot read: No such file"), std::string::npos) << r.err;
  r = test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/nope.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/nope.csv: cannot read"), std::string::npos) << r.err;
  r = test::run_cli("hits --mesh " + dir + "/m.obj");
  EXPECT_EQ(r.status, 2);  // usage: --rays is required
}

TEST(HitsCli, UnwritableOutputIsARuntimeFailure) {
  // Exit 1 (runtime failure, from AtomicFile), not 2: the inputs were fine.
  expect_failure("hits_eout", kTri, "0,0,0,0,0,1\n", 1, "cannot write /nonexistent/dir/x.csv",
                 "/nonexistent/dir/x.csv");
}

TEST(HitsCli, HelpTeachesTheFormats) {
  const auto r = test::run_cli("hits --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("ox,oy,oz,dx,dy,dz,tmin,tmax"), std::string::npos);
  EXPECT_NE(r.out.find("ray,tri,t,u,v"), std::string::npos);
  EXPECT_NE(r.out.find("Example"), std::string::npos);
}

}  // namespace
}  // namespace rayvec
