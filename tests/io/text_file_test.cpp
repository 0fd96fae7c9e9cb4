// read_text_file: the bounded, binary-rejecting reader behind every text input (OBJ, scene JSON,
// rays and mesh CSV). Devices and streams that never end must fail fast with a message, not hang.
#include "io/text_file.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "io/input_error.h"
#include "test_support.h"

namespace rayvec {
namespace {

// The message read_text_file throws for `path` ("" when it does not throw).
std::string error_of(const std::string& path) {
  try {
    read_text_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Sets RAYVEC_MAX_INPUT_MB for one scope.
class InputLimit {
 public:
  explicit InputLimit(const char* mb) { setenv("RAYVEC_MAX_INPUT_MB", mb, 1); }
  ~InputLimit() { unsetenv("RAYVEC_MAX_INPUT_MB"); }
};

TEST(TextFile, EndlessDevicesFailAtOnce) {
  EXPECT_NE(error_of("/dev/zero").find("/dev/zero:1: contains a NUL byte"), std::string::npos)
      << error_of("/dev/zero");
  // Random bytes hold a NUL within the first block with overwhelming probability (1 - 2^-94).
  EXPECT_NE(error_of("/dev/urandom").find("contains a NUL byte"), std::string::npos);
}

TEST(TextFile, RegularFileOverTheLimitIsRefusedBeforeReading) {
  const std::string dir = test::temp_dir("text_file_limit");
  test::write_file(dir + "/big.csv", std::string(1500000, '1'));
  test::write_file(dir + "/small.csv", std::string(900000, '1'));
  InputLimit limit("1");
  const std::string message = error_of(dir + "/big.csv");
  EXPECT_NE(message.find("big.csv: is larger than the 1 MB input limit; set RAYVEC_MAX_INPUT_MB"),
            std::string::npos)
      << message;
  EXPECT_EQ(read_text_file(dir + "/small.csv").size(), 900000u);
}

TEST(TextFile, StreamOverTheLimitStopsAtTheLimit) {
  // A FIFO fed forever (like `yes`) has no size to check up front: the limit must stop the read.
  const std::string fifo = test::temp_dir("text_file_stream") + "/rays.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto old_handler = std::signal(SIGPIPE, SIG_IGN);  // the writer sees EPIPE instead
  std::thread writer([&] {
    const int fd = open(fifo.c_str(), O_WRONLY);
    const std::string line = "0,0,0,0,0,1\n";
    while (fd >= 0 && write(fd, line.data(), line.size()) > 0) {}
    if (fd >= 0) close(fd);
  });
  std::string message;
  {
    InputLimit limit("1");
    message = error_of(fifo);
  }
  writer.join();
  std::signal(SIGPIPE, old_handler);
  EXPECT_NE(message.find("rays.fifo: is larger than the 1 MB input limit"), std::string::npos) << message;
}

TEST(TextFile, LimitFromEnvironmentIgnoresGarbage) {
  {
    InputLimit limit("12");
    EXPECT_EQ(max_input_bytes(), 12000000u);
  }
  {
    InputLimit limit("12x");
    EXPECT_EQ(max_input_bytes(), 4096000000u);
  }
  {
    InputLimit limit("0");
    EXPECT_EQ(max_input_bytes(), 4096000000u);
  }
}

TEST(TextFile, Utf16IsNamedNotCalledBinary) {
  const std::string dir = test::temp_dir("text_file_utf16");
  test::write_file(dir + "/w.obj", std::string("\xFF\xFEv\0 \0", 6));
  EXPECT_NE(error_of(dir + "/w.obj").find("is UTF-16 text"), std::string::npos) << error_of(dir + "/w.obj");
}

// The message TextFile throws for `path` ("" when it does not throw).
std::string mapped_error_of(const std::string& path) {
  try {
    TextFile file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A file of 1 MiB and more is mapped, not copied, and reads as read_text_file reads it; a smaller
// one is read.
TEST(TextFile, BigFilesAreMappedWithTheSameText) {
  const std::string dir = test::temp_dir("text_file_map");
  std::string big = "\xEF\xBB\xBFv 1 2 3\n";
  while (big.size() < (std::size_t(1) << 20) + 7) big += "v 0.5 0.25 0.125\n";
  test::write_file(dir + "/big.obj", big);
  test::write_file(dir + "/small.obj", "v 1 2 3\n");
  const TextFile mapped(dir + "/big.obj");
  EXPECT_TRUE(mapped.mapped());
  EXPECT_EQ(mapped.text(), read_text_file(dir + "/big.obj")) << "the UTF-8 byte-order mark is dropped too";
  const TextFile small(dir + "/small.obj");
  EXPECT_FALSE(small.mapped());
  EXPECT_EQ(small.text(), "v 1 2 3\n");
  TextFile moved(TextFile(dir + "/small.obj"));
  EXPECT_EQ(moved.text(), "v 1 2 3\n");
}

// Binary data, UTF-16 and the size limit get read_text_file's messages when mapped too.
TEST(TextFile, MappedFilesGetTheSameErrors) {
  const std::string dir = test::temp_dir("text_file_map_errors");
  std::string nul(std::size_t(1) << 21, 'v');
  for (std::size_t i = 99; i < nul.size(); i += 100) nul[i] = '\n';
  nul[1500000] = '\0';
  test::write_file(dir + "/nul.obj", nul);
  test::write_file(dir + "/utf16.obj", "\xFF\xFE" + std::string(std::size_t(1) << 20, 'v'));
  for (const char* name : {"/nul.obj", "/utf16.obj"}) {
    const std::string message = mapped_error_of(dir + name);
    EXPECT_FALSE(message.empty()) << name;
    EXPECT_EQ(message, error_of(dir + name));
  }
  InputLimit limit("1");
  EXPECT_NE(mapped_error_of(dir + "/nul.obj").find("is larger than the 1 MB input limit"), std::string::npos);
}

// A mapped file that shrinks under the reader ends the process with a message and status 1, not
// a crash by SIGBUS.
TEST(TextFile, TruncatedWhileMappedEndsWithAMessage) {
  const std::string dir = test::temp_dir("text_file_truncated");
  const std::string path = dir + "/shrinks.obj";
  test::write_file(path, std::string(std::size_t(3) << 20, 'v'));
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const TextFile file(path);
        if (truncate(path.c_str(), 0) != 0) std::_Exit(3);
        // the mapping outlives the names; the process that runs this ends without running exit
        // handlers, so it removes its own directory here
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
        volatile char last = file.text()[file.text().size() - 1];
        (void)last;
        std::_Exit(4);
      },
      testing::ExitedWithCode(1), "shrinks.obj was truncated while it was being read");
}

}  // namespace
}  // namespace rayvec
