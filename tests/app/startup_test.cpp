// Start-up cost: the rayvec binary needs only light shared libraries at start. OpenImageIO (with its
// ~260 dependencies, 0.25 s and 130 MB before main) is loaded only when a file that is neither PNG
// nor EXR is read (docs/benchmarks.md#decision-image-io-without-openimageio), OpenEXR only when an EXR
// is read or written (docs/benchmarks.md#decision-exr-module). A structural check rather than a timed
// one: a new heavy dependency fails it on any machine, however fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "bench/ray_tracer.h"
#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"

namespace rayvec {
namespace {

std::string shell_output(const std::string& cmd) {
  std::string out;
  if (std::FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    std::size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, got);
    ::pclose(p);
  }
  return out;
}

// Every library `ldd` lists for the binary must be one of these (the closure of what rayvec links:
// libc, C++ runtime, OpenMP, GMP, tinyobjloader, libpng with zlib, libjpeg). A new entry costs every command
// its loading time: measure it with scripts/startup_cost.sh and load it on demand if it is heavy,
// before adding it here — as OpenImageIO (librayvec_oiio.so), OpenEXR with Imath
// (librayvec_exr.so), MPI (librayvec_mpi.so) and the Embree rival with TBB (librayvec_embree.so) are.
constexpr std::string_view kAllowed[] = {
    "linux-vdso", "ld-linux-x86-64", "libc", "libm", "libstdc++", "libgcc_s", "libgomp", "libgmp",
    "libtinyobjloader", "libz", "libpng16", "libjpeg",
    // the sanitizer runtimes and GMP's C++ layer, present in the instrumented build only
    "libasan", "libubsan", "libgmpxx"};

// Whether a library file name (libc.so.6, linux-vdso.so.1) is one of kAllowed followed by ".so".
bool allowed(std::string_view name) {
  const std::size_t so = name.find(".so");
  return so != std::string_view::npos &&
         std::find(std::begin(kAllowed), std::end(kAllowed), name.substr(0, so)) != std::end(kAllowed);
}

TEST(Startup, BinaryNeedsOnlyLightSharedLibraries) {
  const std::string ldd = shell_output(std::string("ldd '") + RAYVEC_CLI + "'");
  ASSERT_NE(ldd.find("libc.so"), std::string::npos) << "ldd failed: " << ldd;
  int libraries = 0;
  std::size_t start = 0;
  while (start < ldd.size()) {
    const std::size_t end = ldd.find('\n', start);
    std::string line = ldd.substr(start, end == std::string::npos ? std::string::npos : end - start);
    start = end == std::string::npos ? ldd.size() : end + 1;
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    std::string name = line.substr(first, line.find_first_of(" \t", first) - first);
    name = std::filesystem::path(name).filename().string();
    ++libraries;
    EXPECT_TRUE(allowed(name)) << name << " is loaded by every rayvec command";
  }
  EXPECT_LE(libraries, 24) << ldd;
  EXPECT_EQ(ldd.find("OpenImageIO"), std::string::npos) << ldd;
  EXPECT_EQ(ldd.find("OpenEXR"), std::string::npos) << ldd;
}

// True when the dynamic loader opened `module` (librayvec_oiio.so by default) while `rayvec ARGS` ran.
bool module_loaded_by(const std::string& args, int* status, const std::string& module = "librayvec_oiio.so") {
  const std::string dir = test::temp_dir("ld_debug");
  ::setenv("LD_DEBUG", "files", 1);
  ::setenv("LD_DEBUG_OUTPUT", (dir + "/ld").c_str(), 1);
  *status = test::run_cli(args).status;
  ::unsetenv("LD_DEBUG");
  ::unsetenv("LD_DEBUG_OUTPUT");
  bool loaded = false;
  for (const auto& f : std::filesystem::directory_iterator(dir))
    loaded = loaded || test::read_file(f.path().string()).find(module) != std::string::npos;
  std::filesystem::remove_all(dir);
  return loaded;
}

TEST(Startup, OpenImageIoModuleLoadsOnlyForOtherFormats) {
  const std::string dir = test::temp_dir("module_use");
  write_image(dir + "/a.png", Image(4, 4, {"R", "G", "B"}));
  write_image(dir + "/a.exr", Image(4, 4, {"R", "G", "B"}));
  test::write_file(dir + "/a.ppm", std::string("P6\n1 1\n255\n\0\0\0", 14));
  int status = -1;
  EXPECT_FALSE(module_loaded_by("compare '" + dir + "/a.png' '" + dir + "/a.exr'", &status));
  EXPECT_EQ(status, 0);
  EXPECT_FALSE(module_loaded_by("--help", &status));
  EXPECT_TRUE(module_loaded_by("compare '" + dir + "/a.ppm' '" + dir + "/a.ppm'", &status));
  EXPECT_EQ(status, 0);
  // JPEG, the texture format of most OBJ files, through libjpeg; only CMYK ones need OpenImageIO
  const std::string jpeg = std::string(RAYVEC_TEST_DATA) + "/images/jpeg/";
  EXPECT_FALSE(module_loaded_by("compare '" + jpeg + "prog.jpg' '" + jpeg + "prog.jpg'", &status));
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(module_loaded_by("compare '" + jpeg + "cmyk.jpg' '" + jpeg + "cmyk.jpg'", &status));
  EXPECT_EQ(status, 0);
}

TEST(Startup, MissingModuleIsARuntimeErrorNamingIt) {
  const std::string dir = test::temp_dir("module_missing");
  test::write_file(dir + "/a.ppm", std::string("P6\n1 1\n255\n\0\0\0", 14));
  ::setenv("RAYVEC_OIIO_MODULE", (dir + "/nowhere/librayvec_oiio.so").c_str(), 1);
  const auto r = test::run_cli("compare '" + dir + "/a.ppm' '" + dir + "/a.ppm'");
  ::unsetenv("RAYVEC_OIIO_MODULE");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("a.ppm: reading this format needs OpenImageIO through librayvec_oiio.so"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("RAYVEC_OIIO_MODULE"), std::string::npos) << r.err;
}

// OpenEXR is loaded, through librayvec_exr.so, by the commands that read or write an EXR alone.
TEST(Startup, ExrModuleLoadsOnlyWhenAnExrIsReadOrWritten) {
  const std::string dir = test::temp_dir("exr_module_use");
  write_image(dir + "/a.png", Image(4, 4, {"R", "G", "B"}));
  write_image(dir + "/a.exr", Image(4, 4, {"R", "G", "B"}));
  test::write_file(dir + "/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string render =
      "render '" + dir + "/t.obj' --width 8 --height 8 --spp 1 --threads 1 -q -o '" + dir;
  int status = -1;
  EXPECT_FALSE(module_loaded_by("--help", &status, "librayvec_exr.so"));
  EXPECT_FALSE(module_loaded_by("--help", &status, "libOpenEXR"));
  EXPECT_FALSE(module_loaded_by("compare '" + dir + "/a.png' '" + dir + "/a.png'", &status, "libOpenEXR"));
  EXPECT_EQ(status, 0);
  EXPECT_FALSE(module_loaded_by(render + "/out.png'", &status, "librayvec_exr.so"));
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(module_loaded_by(render + "/out.exr'", &status, "librayvec_exr.so"));
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(module_loaded_by("compare '" + dir + "/a.png' '" + dir + "/a.exr'", &status, "libOpenEXR"));
  EXPECT_EQ(status, 0);
}

// Without the module, reading or writing an EXR fails with exit 1 naming it and how to point to it;
// a render to EXR fails before rendering, leaving no file.
TEST(Startup, MissingExrModuleIsARuntimeErrorNamingIt) {
  const std::string dir = test::temp_dir("exr_module_missing");
  write_image(dir + "/a.exr", Image(4, 4, {"R", "G", "B"}));
  test::write_file(dir + "/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ::setenv("RAYVEC_EXR_MODULE", (dir + "/nowhere/librayvec_exr.so").c_str(), 1);
  const auto read = test::run_cli("compare '" + dir + "/a.exr' '" + dir + "/a.exr'");
  const auto write =
      test::run_cli("render '" + dir + "/t.obj' --width 8 --height 8 --spp 1 -q -o '" + dir + "/out.exr'");
  ::unsetenv("RAYVEC_EXR_MODULE");
  EXPECT_EQ(read.status, 1) << read.err;
  EXPECT_NE(read.err.find("a.exr: reading EXR needs OpenEXR through librayvec_exr.so: librayvec_exr.so not "
                          "found (looked for " +
                          dir + "/nowhere/librayvec_exr.so)"),
            std::string::npos)
      << read.err;
  EXPECT_NE(read.err.find("RAYVEC_EXR_MODULE"), std::string::npos) << read.err;
  EXPECT_EQ(write.status, 1) << write.err;
  EXPECT_NE(write.err.find("writing EXR needs OpenEXR through librayvec_exr.so"), std::string::npos)
      << write.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.exr"));
}

// Embree (and TBB) are loaded by `bench rays --vs-embree` alone, through librayvec_embree.so.
TEST(Startup, EmbreeModuleLoadsOnlyForTheEmbreeComparison) {
  if (!embree_built()) GTEST_SKIP() << "rayvec was built without Embree (libembree-dev)";
  const std::string dir = test::temp_dir("embree_module_use");
  test::write_file(dir + "/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string bench = "bench rays '" + dir + "/t.obj' --size 8x8 --repeats 1 --builds 1 --threads 1";
  int status = -1;
  EXPECT_FALSE(module_loaded_by(bench, &status, "librayvec_embree.so"));
  EXPECT_EQ(status, 0);
  EXPECT_FALSE(module_loaded_by("--help", &status, "libembree3"));
  EXPECT_TRUE(module_loaded_by(bench + " --vs-embree", &status, "librayvec_embree.so"));
  EXPECT_EQ(status, 0);
}

TEST(Startup, MissingEmbreeModuleIsARuntimeErrorNamingIt) {
  if (!embree_built()) GTEST_SKIP() << "rayvec was built without Embree (libembree-dev)";
  const std::string dir = test::temp_dir("embree_module_missing");
  test::write_file(dir + "/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ::setenv("RAYVEC_EMBREE_MODULE", (dir + "/nowhere/librayvec_embree.so").c_str(), 1);
  const auto r = test::run_cli("bench rays '" + dir + "/t.obj' --size 8x8 --repeats 1 --vs-embree");
  ::unsetenv("RAYVEC_EMBREE_MODULE");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("--vs-embree: librayvec_embree.so"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("RAYVEC_EMBREE_MODULE"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rayvec
