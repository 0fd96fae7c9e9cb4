#include "platform/large_buffer.h"

#include <sys/mman.h>

#include <new>

namespace rayvec {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeFrom = std::size_t(4) << 20;  // smaller: the rounding would waste too much

}  // namespace

LargeBuffer allocate_large_buffer(std::size_t bytes) {
  const std::size_t align = bytes >= kHugeFrom ? kHugePage : 64;
  const std::size_t size = bytes == 0 ? align : (bytes + align - 1) / align * align;
  void* p = std::aligned_alloc(align, size);
  if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  if (align == kHugePage) madvise(p, size, MADV_HUGEPAGE);  // advice only: a refusal changes nothing
#endif
  return LargeBuffer(p);
}

}  // namespace rayvec
