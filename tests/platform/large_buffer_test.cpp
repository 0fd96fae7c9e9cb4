// LargeBuffer: 64-byte aligned below 4 MiB, 2 MiB aligned (huge-page candidates) from there, and
// the whole requested size writable (the size is rounded up, never down).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "platform/large_buffer.h"

namespace rayvec {
namespace {

std::uintptr_t address(const LargeBuffer& b) { return reinterpret_cast<std::uintptr_t>(b.get()); }

TEST(LargeBuffer, SmallBuffersAreCacheLineAligned) {
  for (std::size_t bytes : {std::size_t(0), std::size_t(1), std::size_t(100), std::size_t(3) << 20}) {
    const LargeBuffer b = allocate_large_buffer(bytes);
    ASSERT_NE(b.get(), nullptr) << bytes;
    EXPECT_EQ(address(b) % 64, 0u) << bytes;
    std::memset(b.get(), 0x5a, bytes);
  }
}

TEST(LargeBuffer, BigBuffersStartOnAHugePageAndAreFullyWritable) {
  const std::size_t bytes = (std::size_t(5) << 20) + 3;  // not a multiple of anything
  const LargeBuffer b = allocate_large_buffer(bytes);
  ASSERT_NE(b.get(), nullptr);
  EXPECT_EQ(address(b) % (std::size_t(2) << 20), 0u);
  auto* p = static_cast<unsigned char*>(b.get());
  std::memset(p, 0xa5, bytes);
  EXPECT_EQ(p[0], 0xa5);
  EXPECT_EQ(p[bytes - 1], 0xa5);
}

}  // namespace
}  // namespace rayvec
