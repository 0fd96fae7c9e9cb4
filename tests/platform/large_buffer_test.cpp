// LargeBuffer: 64-byte aligned below 2 MiB, 2 MiB aligned (huge-page candidates) from there, and
// the whole requested size writable (the size is rounded up, never down).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include <vector>

#include "platform/large_buffer.h"

namespace rayvec {
namespace {

std::uintptr_t address(const LargeBuffer& b) { return reinterpret_cast<std::uintptr_t>(b.get()); }

TEST(LargeBuffer, SmallBuffersAreCacheLineAligned) {
  for (std::size_t bytes : {std::size_t(0), std::size_t(1), std::size_t(100), (std::size_t(2) << 20) - 1}) {
    const LargeBuffer b = allocate_large_buffer(bytes);
    ASSERT_NE(b.get(), nullptr) << bytes;
    EXPECT_EQ(address(b) % 64, 0u) << bytes;
    std::memset(b.get(), 0x5a, bytes);
  }
}

TEST(LargeBuffer, BigBuffersStartOnAHugePageAndAreFullyWritable) {
  const std::size_t bytes = (std::size_t(2) << 20) + 3;  // not a multiple of anything
  const LargeBuffer b = allocate_large_buffer(bytes);
  ASSERT_NE(b.get(), nullptr);
  EXPECT_EQ(address(b) % (std::size_t(2) << 20), 0u);
  auto* p = static_cast<unsigned char*>(b.get());
  std::memset(p, 0xa5, bytes);
  EXPECT_EQ(p[0], 0xa5);
  EXPECT_EQ(p[bytes - 1], 0xa5);
}

TEST(LargeAllocator, VectorsOfAHugePageOrMoreStartOnOne) {
  std::vector<float, LargeAllocator<float>> big(std::size_t(1) << 19);  // 2 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % (std::size_t(2) << 20), 0u);
  EXPECT_EQ(big.back(), 0.0f);  // value-initialized as with the default allocator
  std::vector<float, LargeAllocator<float>> small(100, 1.5f);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % 64, 0u);
  EXPECT_EQ(small.back(), 1.5f);
}

}  // namespace
}  // namespace rayvec
