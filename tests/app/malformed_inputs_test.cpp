// Malformed inputs end to end through the CLI: assimp's invalid and odd OBJ test models
// (tests/data/malformed/assimp/, BSD-3-clause, see its README.md) and our own broken files. Every
// rejection must exit 2 (1 for an unwritable output), say `file:line:` where a line exists, name
// what is wrong, and leave no output file (neither the file nor an AtomicFile temporary).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "image/image_io.h"
#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(RAYVEC_TEST_DATA) + "/malformed/assimp/";
const std::string kTri = "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n";
const std::string kRay = "0.2,0.2,0,0,0,1\n";

// True when `dir` holds no file whose name starts with `stem` (the output or its temporaries).
bool no_output(const std::string& dir, const std::string& stem) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(stem, 0) == 0) return false;
  return true;
}

// Runs `rayvec hits` on `obj` (a path) and `rays` (a path) writing <dir>/out.csv.
test::CommandResult hits(const std::string& dir, const std::string& obj, const std::string& rays) {
  return test::run_cli("hits --mesh '" + obj + "' --rays '" + rays + "' -o '" + dir + "/out.csv'");
}

// Writes `obj_text` and `rays_text` into a fresh directory, runs `hits`, and checks the rejection.
void expect_hits_rejects(const std::string& name, const std::string& obj_text, const std::string& rays_text,
                         const std::string& message) {
  const std::string dir = test::temp_dir("malformed_" + name);
  test::write_file(dir + "/m.obj", obj_text);
  test::write_file(dir + "/r.csv", rays_text);
  const auto r = hits(dir, dir + "/m.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 2) << name << ": " << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << name << ": expected '" << message << "' in: " << r.err;
  EXPECT_TRUE(no_output(dir, "out.csv")) << name;
  EXPECT_LT(r.err.size(), 1000u) << name << ": the message should be short";
}

void expect_assimp_rejected(const std::string& file, const std::string& message) {
  const std::string dir = test::temp_dir("malformed_assimp");
  test::write_file(dir + "/r.csv", kRay);
  const auto r = hits(dir, kData + file, dir + "/r.csv");
  EXPECT_EQ(r.status, 2) << file << ": " << r.err;
  EXPECT_NE(r.err.find(kData + file + message), std::string::npos)
      << file << ": expected '" << message << "' in: " << r.err;
  EXPECT_TRUE(no_output(dir, "out.csv")) << file;
}

TEST(MalformedInputs, AssimpInvalidModelsAreRejectedWithFileAndLine) {
  expect_assimp_rejected("empty.obj", ": no triangles");
  expect_assimp_rejected("malformed.obj", ":28: face corner 1: vertex index '0' is 0");
  expect_assimp_rejected("malformed2.obj", ":23: a face needs at least 3 corners, found 0");
  expect_assimp_rejected("number_formats.obj", ":11: `v` coordinate 3 '3.1+e2' is not a finite number");
}

TEST(MalformedInputs, AssimpOddModelsAreRejectedOrReadAsDocumented) {
  expect_assimp_rejected("box_UTF16BE.obj", ": is UTF-16 text");
  // Point clouds and lines only: no faces to trace.
  expect_assimp_rejected("point_cloud.obj", ": no triangles");
  expect_assimp_rejected("testpoints.obj", ": no triangles");
  expect_assimp_rejected("testline.obj", ": no triangles");
  // Accepted: no final newline, a ring (a concave polygon with a bridged hole: 66 corners, 64
  // triangles), runs of spaces.
  const std::string dir = test::temp_dir("malformed_assimp_ok");
  test::write_file(dir + "/r.csv", kRay);
  for (const auto& [file, triangles] :
       {std::pair<std::string, std::string>{"box_without_lineending.obj", "12"},
        {"concave_polygon.obj", "64"},
        {"multiple_spaces.obj", "1"}}) {
    const auto r = hits(dir, kData + file, dir + "/r.csv");
    EXPECT_EQ(r.status, 0) << file << ": " << r.err;
    EXPECT_NE(r.err.find(" " + triangles + " triangles"), std::string::npos) << file << ": " << r.err;
  }
}

TEST(MalformedInputs, TruncatedAndJunkObjFilesNameTheLine) {
  expect_hits_rejects("trunc_v", "v 0 0 0\nv 1 0 0\nv 0 1", kRay,
                      "m.obj:3: `v` needs 3 coordinates, found 2");
  expect_hits_rejects("trunc_f", kTri + "f 1 2", kRay, "m.obj:5: a face needs at least 3 corners, found 2");
  expect_hits_rejects("nul", kTri + std::string("v 0 0 \0\x01\x02", 9), kRay,
                      "m.obj:5: contains a NUL byte: this is binary data, not a text file");
  expect_hits_rejects("junk", kTri + "v 0 \x01\xff\xfe 1\n", kRay,
                      "m.obj:5: `v` coordinate 2 '\\x01\\xFF\\xFE' is not a finite number");
  expect_hits_rejects("utf16le", std::string("\xff\xfev\0 \0", 6), kRay, "m.obj: is UTF-16 text");
}

TEST(MalformedInputs, NonFiniteVerticesAndBadIndicesAreRejected) {
  expect_hits_rejects("nan", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", kRay,
                      "m.obj:2: `v` coordinate 1 'nan' is not a finite number");
  expect_hits_rejects("inf", "v 0 0 0\nv 0 -inf 0\nv 0 1 0\nf 1 2 3\n", kRay,
                      "m.obj:2: `v` coordinate 2 '-inf' is not a finite number");
  expect_hits_rejects("big", "v 0 0 1e39\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", kRay,
                      "m.obj:1: `v` coordinate 3 '1e39' is not a finite number");
  // Beyond double's range: from_chars reports out-of-range and leaves its output at 0.
  expect_hits_rejects("e400", "v 0 0 1e400\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", kRay,
                      "m.obj:1: `v` coordinate 3 '1e400' is not a finite number");
  // Lone CR line ends (old Mac files), which tinyobjloader honours: every line is still checked.
  expect_hits_rejects("cr_nan", "v 0 0 0\rv nan 0 0\rv 0 1 0\rf 1 2 3\r", kRay,
                      "m.obj:2: `v` coordinate 1 'nan' is not a finite number");
  expect_hits_rejects("cr_range", "v 0 0 0\rv 1 0 0\r\nv 0 1 0\rf 1 2 7\r", kRay,
                      "m.obj:4: face vertex index 7 is out of range: the file defines 3 vertices");
  expect_hits_rejects("neg", kTri + "f -1 -2 -4\n", kRay,
                      "m.obj:5: face corner 3: vertex index '-4' is out of range: only 3 vertices");
  expect_hits_rejects("range", kTri + "f 1 2 4\n", kRay, "m.obj:5: face vertex index 4 is out of range");
  expect_hits_rejects("hugeidx", kTri + "f 1 2 99999999999999999999\n", kRay,
                      "m.obj:5: face corner 3: vertex index '99999999999999999999' is not an integer");
  expect_hits_rejects("vn", kTri + "f 1//1 2//1 3//1\n", kRay,
                      "m.obj:5: face normal index 1 is out of range");
  expect_hits_rejects("one", kTri + "f 1\n", kRay, "m.obj:5: a face needs at least 3 corners, found 1");
  expect_hits_rejects("two", kTri + "f 1 2\n", kRay, "m.obj:5: a face needs at least 3 corners, found 2");
}

TEST(MalformedInputs, AMillionCornersOnOneLineIsRejectedQuickly) {
  // tinyobjloader's ear clipping would take hours on this face; the scan stops at the limit.
  std::string obj;
  for (int i = 0; i < 3; ++i) obj += "v " + std::to_string(i) + " " + std::to_string(i * i) + " 0\n";
  obj += "f";
  for (int i = 0; i < 1000000; ++i) obj += " " + std::to_string(1 + i % 3);
  expect_hits_rejects("million_f", obj + "\n", kRay, "m.obj:4: a face with more than 10000 corners");
  // A million numbers on one `v` line: the extra ones are ignored, quickly.
  std::string v = "v";
  for (int i = 0; i < 1000000; ++i) v += " 1";
  const std::string dir = test::temp_dir("malformed_million_v");
  test::write_file(dir + "/m.obj", v + "\n" + kTri + "f 2 3 4\n");
  test::write_file(dir + "/r.csv", kRay);
  const auto r = hits(dir, dir + "/m.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(MalformedInputs, MissingMtlAndTextureAreWarnings) {
  const std::string dir = test::temp_dir("malformed_mtl");
  test::write_file(dir + "/m.obj", "mtllib nope.mtl\n" + kTri);
  test::write_file(dir + "/t.obj", "mtllib t.mtl\nusemtl a\n" + kTri);
  test::write_file(dir + "/t.mtl", "newmtl a\nKd 1 1 1\nmap_Kd missing.png\n");
  test::write_file(dir + "/r.csv", kRay);
  auto r = hits(dir, dir + "/m.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + dir + "/m.obj: material file " + dir + "/nope.mtl not found"),
            std::string::npos)
      << r.err;
  // A device as material file would be read forever.
  test::write_file(dir + "/z.obj", "mtllib /dev/zero\n" + kTri);
  r = hits(dir, dir + "/z.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("material file /dev/zero is not a regular file"), std::string::npos) << r.err;
  r = hits(dir, dir + "/t.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + dir + "/t.mtl:3: material 'a': texture 'missing.png' (" + dir +
                       "/missing.png) not found; drawn with Kd only"),
            std::string::npos)
      << r.err;
}

// Renders `mtl` (as m.mtl, material `a` on a triangle facing the default camera) to an EXR.
test::CommandResult render_mtl(const std::string& dir, const std::string& mtl,
                               const std::string& extra = "") {
  test::write_file(dir + "/m.mtl", mtl);
  test::write_file(dir + "/m.obj", "mtllib m.mtl\nusemtl a\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  return test::run_cli("render -q " + dir + "/m.obj --width 24 --height 18 -o " + dir + "/out.exr " + extra);
}

int non_finite_pixels(const std::string& exr) {
  const Image img = read_image(exr);
  int bad = 0;
  for (float v : img.pixels) bad += std::isfinite(v) ? 0 : 1;
  return bad;
}

TEST(MalformedInputs, MtlValuesOutOfRangeAreClampedAndNoNanOrInfReachesTheImage) {
  const std::string dir = test::temp_dir("malformed_mtl_values");
  for (const std::string& mtl :
       {std::string("newmtl a\nKd 0.5 0.5 0.5\nKs 1 1 1\nNi -1\nTf 1 1 1\nd 0.5\nillum 7\n"),
        std::string("newmtl a\nKd 1e38 1e38 1e38\nillum 3\n"), std::string("newmtl a\nKs 1e38\nillum 3\n"),
        std::string("newmtl a\nKd 1\nKs 1\nNs 1e38\nillum 2\n"),
        std::string("newmtl a\nKe 3e38 0 0\nillum 1\n")}) {
    const auto r = render_mtl(dir, mtl);
    EXPECT_EQ(r.status, 0) << mtl << r.err;
    EXPECT_NE(r.err.find(dir + "/m.mtl:"), std::string::npos) << mtl << ": the warning names the MTL line";
    EXPECT_EQ(non_finite_pixels(dir + "/out.exr"), 0) << mtl;
  }
  // A value no float holds is an error naming the line; --strict makes the clamps errors.
  auto r = render_mtl(dir, "newmtl a\nKd 1e39 0 0\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/m.mtl:2: `Kd` value '1e39' is not a finite number"), std::string::npos)
      << r.err;
  r = render_mtl(dir, "newmtl a\nillum 11\n", "--strict");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/m.mtl:2: material 'a': `illum 11` is not an MTL illumination model"),
            std::string::npos)
      << r.err;
}

TEST(MalformedInputs, TexturesThatNeverEndAreWarningsNotHangs) {
  const std::string dir = test::temp_dir("malformed_mtl_devices");
  ASSERT_EQ(mkfifo((dir + "/fifo.png").c_str(), 0600), 0);
  for (const std::string tex : {"/dev/zero", "/dev/urandom", "fifo.png"}) {
    const auto r = render_mtl(dir, "newmtl a\nKd 1 1 1\nmap_Kd " + tex + "\n");
    EXPECT_EQ(r.status, 0) << tex << r.err;
    EXPECT_NE(r.err.find("m.mtl:3: material 'a': texture '" + tex + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is not a regular file; drawn with Kd only"), std::string::npos) << r.err;
  }
  std::filesystem::remove(dir + "/out.exr");
  const auto r = render_mtl(dir, "newmtl a\nmap_Kd /dev/zero\n", "--strict");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(no_output(dir, "out.exr"));
}

TEST(MalformedInputs, MtlFilesHaveTheInputLimitAndTheNulCheck) {
  const std::string dir = test::temp_dir("malformed_mtl_limits");
  test::write_file(dir + "/m.obj", "mtllib m.mtl\n" + kTri);
  {  // 200 MB, sparse: judged by its size before any byte is read
    std::ofstream(dir + "/m.mtl").close();
    ASSERT_EQ(truncate((dir + "/m.mtl").c_str(), 200000000), 0);
  }
  setenv("RAYVEC_MAX_INPUT_MB", "100", 1);  // the child inherits it
  auto r = test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/out.png");
  unsetenv("RAYVEC_MAX_INPUT_MB");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("m.mtl: is larger than the 100 MB input limit"), std::string::npos) << r.err;
  r = test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/out.png");
  EXPECT_EQ(r.status, 2) << r.err;  // all NUL bytes
  EXPECT_NE(r.err.find("m.mtl:1: contains a NUL byte"), std::string::npos) << r.err;
  EXPECT_TRUE(no_output(dir, "out.png"));
}

// A limit that is not a number would silently be the default (the user meant another): refused
// before the command starts, naming the variable.
TEST(MalformedInputs, AnInputLimitThatIsNotANumberIsRefused) {
  const std::string dir = test::temp_dir("malformed_limit_env");
  test::write_file(dir + "/m.obj", kTri);
  const std::string render = "render -q " + dir + "/m.obj --width 8 --height 8 -o " + dir + "/out.png";
  for (const char* value : {"abc", "0", "-5", "1e3", " 5", "1099511627776", "99999999999999999999"}) {
    setenv("RAYVEC_MAX_INPUT_MB", value, 1);
    const auto r = test::run_cli(render);
    unsetenv("RAYVEC_MAX_INPUT_MB");
    EXPECT_EQ(r.status, 2) << value << ": " << r.err;
    EXPECT_NE(r.err.find("RAYVEC_MAX_INPUT_MB: '" + std::string(value) + "' is not a number of megabytes"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(no_output(dir, "out.png")) << value;
  }
  for (const char* value : {"1", "16000", "1099511627775"}) {
    setenv("RAYVEC_MAX_INPUT_MB", value, 1);
    const auto r = test::run_cli(render);
    const auto info = test::run_cli("info");
    unsetenv("RAYVEC_MAX_INPUT_MB");
    EXPECT_EQ(r.status, 0) << value << ": " << r.err;
    EXPECT_NE(info.out.find("input limit: " + std::string(value) + " MB (RAYVEC_MAX_INPUT_MB)"),
              std::string::npos)
        << info.out;
  }
  // help and info read no input: they run, and info names the problem
  setenv("RAYVEC_MAX_INPUT_MB", "abc", 1);
  const auto help = test::run_cli("render --help");
  const auto info = test::run_cli("info");
  unsetenv("RAYVEC_MAX_INPUT_MB");
  EXPECT_EQ(help.status, 0) << help.err;
  EXPECT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("input limit: 4096 MB; RAYVEC_MAX_INPUT_MB: 'abc' is not a number"),
            std::string::npos)
      << info.out;
  EXPECT_NE(test::run_cli("info").out.find("input limit: 4096 MB (the default"), std::string::npos);
}

TEST(MalformedInputs, Utf8ByteOrderMarkIsIgnored) {
  // Without dropping the mark, "\xEF\xBB\xBFv" is an unknown keyword: vertex 1 would vanish and
  // every face index would shift by one.
  const std::string dir = test::temp_dir("malformed_bom");
  test::write_file(dir + "/m.obj", "\xEF\xBB\xBF" + kTri);
  test::write_file(dir + "/r.csv", "\xEF\xBB\xBF" + kRay);
  const auto r = hits(dir, dir + "/m.obj", dir + "/r.csv");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_file(dir + "/out.csv").rfind("ray,tri,t,u,v\n0,0,1,", 0), 0u);  // hit at t = 1
}

TEST(MalformedInputs, BrokenCsvFilesNameTheLine) {
  expect_hits_rejects("csv_trunc", kTri, "0,0,0,0,0,1\n0,0,0,0,0,", "r.csv:2: field 6 '' is empty");
  expect_hits_rejects("csv_cut", kTri, "0,0,0,0,0,1\n0,0,0,0", "r.csv:2: found 4 fields, expected 6");
  expect_hits_rejects("csv_nul", kTri, std::string("0,0,0,0,0,1\n\0\0", 14), "r.csv:2: contains a NUL byte");
  expect_hits_rejects("csv_junk", kTri, "0,0,0,0,0,\x80\x81\n",
                      "r.csv:1: field 6 '\\x80\\x81' is not a number");
  expect_hits_rejects("csv_long", kTri, "0,0,0,0,0," + std::string(100000, '7') + "x\n",
                      "r.csv:1: field 6 '7777777777777777777777777777777777777777...' is not a number");
  // Visibility inputs.
  const std::string dir = test::temp_dir("malformed_vis");
  test::write_file(dir + "/v.csv", "0,0,1\n1,0,1\n0,1\n");
  test::write_file(dir + "/f.csv", "0,1,2\n");
  auto r =
      test::run_cli("visibility --verts " + dir + "/v.csv --faces " + dir + "/f.csv -o " + dir + "/out.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/v.csv:3: found 2 fields, expected 3"), std::string::npos) << r.err;
  EXPECT_TRUE(no_output(dir, "out.txt"));
}

// Writes scene.json (with `json`) next to a valid m.obj and runs `render` into out.png.
void expect_render_rejects(const std::string& name, const std::string& json, const std::string& message,
                           const std::string& extra_args = "") {
  const std::string dir = test::temp_dir("malformed_" + name);
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/s.json", json);
  const auto r = test::run_cli("render -q " + dir + "/s.json -o " + dir + "/out.png " + extra_args);
  EXPECT_EQ(r.status, 2) << name << ": " << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << name << ": expected '" << message << "' in: " << r.err;
  EXPECT_TRUE(no_output(dir, "out.png")) << name;
}

const std::string kObjects = R"("objects": [{"obj": "m.obj"}])";

TEST(MalformedInputs, SceneJsonOfTheWrongTypesIsRejected) {
  expect_render_rejects("json_trunc", "{" + kObjects + ", \"camera\": {\"width\": 6",
                        "s.json:1: invalid JSON");
  expect_render_rejects("json_array", "[1, 2]", "expected an object");
  expect_render_rejects("json_objects", R"({"objects": {"obj": "m.obj"}})",
                        "objects: expected a non-empty array of objects");
  expect_render_rejects("json_width", "{" + kObjects + R"(, "camera": {"width": "640"}})",
                        "camera.width: expected an integer, got string");
  expect_render_rejects("json_fov", "{" + kObjects + R"(, "camera": {"fov_y": [45]}})",
                        "camera.fov_y: expected a number, got array");
  expect_render_rejects("json_light", "{" + kObjects + R"(, "lights": [{"type": 3}]})",
                        "lights[0].type: expected a string, got number");
  expect_render_rejects("json_obj", R"({"objects": [{"obj": 7}]})", "objects[0].obj: expected a string");
  expect_render_rejects("json_missing_obj", R"({"objects": [{"obj": "nope.obj"}]})", "nope.obj: cannot read");
  // A missing texture is a warning (the material keeps Kd), an error under --strict.
  expect_render_rejects("json_texture",
                        R"({"objects": [{"obj": "m.obj", "material": {"map_Kd": "nope.png"}}]})",
                        "nope.png not found", "--strict");
  expect_render_rejects("json_deep", std::string(100000, '[') + std::string(100000, ']'),
                        "expected an object");
}

TEST(MalformedInputs, AbsurdImageSizesAndDepthsAreRejectedBeforeWork) {
  for (const std::string size : {"0", "-5", "1000000"})
    expect_render_rejects("json_size" + size, "{" + kObjects + R"(, "camera": {"width": )" + size + "}}",
                          "s.json:1: camera.width: must be between 1 and 16384");
  expect_render_rejects("json_height", "{" + kObjects + R"(, "camera": {"height": 1000000}})",
                        "camera.height: must be between 1 and 16384");
  expect_render_rejects("json_depth", "{" + kObjects + R"(, "render": {"max_depth": 1000000}})",
                        "render.max_depth: must be between 0 and 64");
  expect_render_rejects("cli_size", "{" + kObjects + "}", "--width/--height: must be between 1 and 16384",
                        "--width 1000000 --height 1000000");
  expect_render_rejects("cli_depth", "{" + kObjects + "}", "--max-depth: must be between 0 and 64",
                        "--max-depth 1000000");
}

// Cameras whose float look-at frame would be NaN or Inf (every camera ray NaN: an image of background
// and exit 0) are refused, naming the value, in a scene file and on the command line alike; so are
// lights whose position or direction the float shading would turn into NaN (an unlit image).
TEST(MalformedInputs, CamerasAndLightsWithoutFloatGeometryAreRejected) {
  const auto camera = [](const std::string& fields) {
    return "{" + kObjects + R"(, "camera": {)" + fields + "}}";
  };
  expect_render_rejects("cam_eye", camera(R"("eye": [1e30, 0, 0])"), "s.json:1: camera.eye: is beyond ±1e10");
  expect_render_rejects("cam_look", camera(R"("look_at": [0, 1e30, 0])"), "camera.look_at: is beyond ±1e10");
  expect_render_rejects("cam_up_huge", camera(R"("up": [1e30, 1e30, 0])"),
                        "camera.up: needs its largest component between 1e-6 and 1e16");
  expect_render_rejects("cam_up_tiny", camera(R"("up": [0, 1e-30, 0])"),
                        "camera.up: needs its largest component between 1e-6 and 1e16");
  expect_render_rejects("cam_up_parallel", camera(R"("eye": [0, 0, 5], "up": [0, 0, -3])"),
                        "camera.up: must not be zero or parallel");
  expect_render_rejects("cam_same", camera(R"("eye": [1, 2, 3], "look_at": [1, 2, 3])"),
                        "camera.look_at: the eye must differ");
  expect_render_rejects("cam_close", camera(R"("eye": [1e-30, 0, 0], "look_at": [0, 0, 0])"),
                        "camera.look_at: is too close to the eye");
  const auto light = [](const std::string& fields) {
    return "{" + kObjects + R"(, "lights": [{)" + fields + "}]}";
  };
  expect_render_rejects("light_far", light(R"("type": "point", "position": [0, 1e30, 0])"),
                        "lights[0].position: is beyond ±1e10");
  expect_render_rejects("light_zero", light(R"("type": "directional", "direction": [0, 0, 0])"),
                        "lights[0].direction: must not be zero");
  for (const char* d : {"[1e-30, 0, -1e-30]", "[1e30, 0, -1e30]"})
    expect_render_rejects("light_dir", light(std::string(R"("type": "directional", "direction": )") + d),
                          "lights[0].direction: needs its largest component between 1e-6 and 1e16");
  expect_render_rejects("cli_eye", "{" + kObjects + "}", "--eye: is beyond ±1e10",
                        "--eye 1e30,0,0 --look-at 0,0,0");
  expect_render_rejects("cli_look", "{" + kObjects + "}", "--look-at: is beyond ±1e10",
                        "--look-at 0,0,-2e10");
  expect_render_rejects("cli_up", "{" + kObjects + "}", "--up: needs its largest component",
                        "--up 1e30,1e30,0");
  expect_render_rejects("cli_close", "{" + kObjects + "}", "--look-at: is too close to the eye",
                        "--eye 1e-30,0,0 --look-at 0,0,0");
}

TEST(MalformedInputs, UnwritableOutputIsExitOneAndCreatesNothing) {
  const std::string dir = test::temp_dir("malformed_unwritable");
  test::write_file(dir + "/m.obj", kTri);
  test::write_file(dir + "/r.csv", kRay);
  for (const std::string& out : {std::string("/nonexistent/dir/x.csv"), dir, dir + "/m.obj/x.csv"}) {
    const auto r = test::run_cli("hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv -o '" + out + "'");
    EXPECT_EQ(r.status, 1) << out << ": " << r.err;
    EXPECT_NE(r.err.find("cannot write " + out), std::string::npos) << r.err;
  }
  EXPECT_EQ(test::read_file(dir + "/m.obj"), kTri);  // untouched
  for (const std::string& out : {std::string("/nonexistent/dir/x.png"), dir + "/m.obj/x.png"}) {
    const auto r = test::run_cli("render -q " + dir + "/m.obj --width 8 --height 8 -o '" + out + "'");
    EXPECT_EQ(r.status, 1) << out << ": " << r.err;
    EXPECT_NE(r.err.find("cannot write " + out), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace rayvec
