// The progress displays on stderr: off a terminal a stage is one line and a bar is not drawn; on a
// terminal (here a pseudo-terminal in place of stderr) both redraw one line in place.
#include "io/progress.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

namespace rayvec {
namespace {

// What `body` writes to stderr while stderr is a pseudo-terminal in raw mode (no "\n" -> "\r\n").
std::string stderr_on_a_terminal(const std::function<void()>& body) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
    ADD_FAILURE() << "no pseudo-terminal";
    return {};
  }
  const int slave = open(ptsname(master), O_RDWR | O_NOCTTY);
  termios raw{};
  tcgetattr(slave, &raw);
  cfmakeraw(&raw);
  tcsetattr(slave, TCSANOW, &raw);
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  dup2(slave, STDERR_FILENO);
  body();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  close(slave);
  std::string out;
  fcntl(master, F_SETFL, O_NONBLOCK);
  char buf[4096];
  for (ssize_t n; (n = read(master, buf, sizeof buf)) > 0;) out.append(buf, std::size_t(n));
  close(master);
  return out;
}

TEST(StageLine, OffATerminalEachStageIsALine) {
  testing::internal::CaptureStderr();  // a file: not a terminal
  {
    const StageLine stages("bench rays");
    stages.progress()("loading");
    stages.show("tracing");
    stages.clear();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "bench rays: loading\nbench rays: tracing\n");
}

TEST(StageLine, OnATerminalRedrawsOneLineAndClearsItWhenDone) {
  const std::string out = stderr_on_a_terminal([] {
    const StageLine stages("bench paper");
    stages.show("a");
    stages.show("b");
  });
  EXPECT_EQ(out, "\r\033[Kbench paper: a\r\033[Kbench paper: b\r\033[K");
}

TEST(ProgressBar, OffATerminalDrawsNothing) {
  testing::internal::CaptureStderr();
  {
    ProgressBar bar(true);
    EXPECT_FALSE(bar.enabled());
    EXPECT_FALSE(bar.progress());
    bar.update(0.5);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(ProgressBar, OnATerminalRedrawsOnlyWhenThePercentageChangesAndEndsTheLineOnce) {
  const std::string out = stderr_on_a_terminal([] {
    ProgressBar bar(true);
    ASSERT_TRUE(bar.enabled());
    const auto progress = bar.progress();
    progress(0.5);
    progress(0.501);  // still 50 %
    bar.update(1.0);
    bar.finish();  // the end of the bar adds nothing more
  });
  const std::string half = "[" + std::string(20, '#') + std::string(20, '.') + "]  50%";
  const std::string full = "[" + std::string(40, '#') + "] 100%";
  EXPECT_EQ(out, "\r\033[K" + half + "\r\033[K" + full + "\n");
  const std::string unwanted = stderr_on_a_terminal([] {
    ProgressBar bar(false);
    bar.update(0.5);
  });
  EXPECT_EQ(unwanted, "");
}

}  // namespace
}  // namespace rayvec
