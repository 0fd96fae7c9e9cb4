// AtomicFile on every kind of target: a regular file is replaced by rename; a symbolic link keeps
// being a link (its target is written atomically); a FIFO or a character device is written
// through, never replaced; a dangling link, a socket or a block device is refused as bad input.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <future>
#include <string>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "test_support.h"

namespace rayvec {
namespace {

namespace fs = std::filesystem;

void write_through(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  std::fputs(text.c_str(), file.stream());
  file.commit();
}

bool only_entries(const std::string& dir, std::size_t n) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())) == n;
}

TEST(AtomicFile, ReplacesARegularFile) {
  const std::string dir = test::temp_dir("atomic_regular");
  test::write_file(dir + "/out.csv", "old\n");
  write_through(dir + "/out.csv", "new\n");
  EXPECT_EQ(test::read_file(dir + "/out.csv"), "new\n");
  EXPECT_TRUE(only_entries(dir, 1));
}

TEST(AtomicFile, WritesTheTargetOfASymlinkAndKeepsTheLink) {
  const std::string dir = test::temp_dir("atomic_symlink");
  fs::create_directories(dir + "/data");
  test::write_file(dir + "/data/real.csv", "old\n");
  fs::create_symlink("data/real.csv", dir + "/link.csv");
  write_through(dir + "/link.csv", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_EQ(test::read_file(dir + "/data/real.csv"), "new\n");
  EXPECT_TRUE(only_entries(dir + "/data", 1));  // the temporary sat beside the target
  EXPECT_TRUE(only_entries(dir, 2));
}

TEST(AtomicFile, RefusesADanglingSymlink) {
  const std::string dir = test::temp_dir("atomic_dangling");
  fs::create_symlink("nowhere/x.csv", dir + "/link.csv");
  try {
    write_through(dir + "/link.csv", "new\n");
    ADD_FAILURE() << "a dangling link was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  dir + "/link.csv: is a symbolic link to nowhere/x.csv, which does not exist"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_TRUE(only_entries(dir, 1));
}

TEST(AtomicFile, WritesThroughAFifoWithoutReplacingIt) {
  const std::string dir = test::temp_dir("atomic_fifo");
  const std::string fifo = dir + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return test::read_file(fifo); });
  write_through(fifo, "through the pipe\n");
  EXPECT_EQ(reader.get(), "through the pipe\n");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_TRUE(only_entries(dir, 1));
}

TEST(AtomicFile, WritesThroughACharacterDeviceWithoutReplacingIt) {
  const std::string dir = test::temp_dir("atomic_chardev");
  const std::string null = dir + "/null";
  // A private copy of /dev/null (character device 1:3): creating one needs root.
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "cannot create a device node (needs root)";
  write_through(null, "discarded\n");
  struct stat st {};
  ASSERT_EQ(::lstat(null.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "the device was replaced by a regular file";
  EXPECT_TRUE(only_entries(dir, 1));
}

TEST(AtomicFile, RefusesASocket) {
  const std::string dir = test::temp_dir("atomic_socket");
  const std::string path = dir + "/sock";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof addr.sun_path);
  std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_THROW(write_through(path, "x"), InputError);
  ::close(fd);
  struct stat st {};
  ASSERT_EQ(::lstat(path.c_str(), &st), 0);
  EXPECT_TRUE(S_ISSOCK(st.st_mode));
}

TEST(AtomicFile, CliWritesThroughASymlinkAndRefusesADanglingOneWithExitTwo) {
  const std::string dir = test::temp_dir("atomic_cli");
  test::write_file(dir + "/m.obj", "v 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\n");
  test::write_file(dir + "/r.csv", "0.2,0.2,0,0,0,1\n");
  test::write_file(dir + "/real.csv", "old\n");
  fs::create_symlink("real.csv", dir + "/link.csv");
  const std::string hits = "hits --mesh " + dir + "/m.obj --rays " + dir + "/r.csv -o ";
  auto r = test::run_cli(hits + dir + "/link.csv");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_EQ(test::read_file(dir + "/real.csv").rfind("ray,tri,t,u,v\n", 0), 0u);
  fs::create_symlink("gone.csv", dir + "/dangling.csv");
  r = test::run_cli(hits + dir + "/dangling.csv");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is a symbolic link to gone.csv, which does not exist"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir + "/dangling.csv"));
}

}  // namespace
}  // namespace rayvec
