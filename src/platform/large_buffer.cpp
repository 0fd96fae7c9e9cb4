#include "platform/large_buffer.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace rayvec {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
// From one huge page up; smaller, rounding up to a whole huge page would waste more than half of it.
constexpr std::size_t kHugeFrom = kHugePage;

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

void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  if (bytes < kHugeFrom) return;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) / kHugePage * kHugePage;
  const std::uintptr_t last = (begin + bytes) / kHugePage * kHugePage;
  if (first < last) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // advice only
#else
  (void)data;
  (void)bytes;
#endif
}

void prefault_pages(const void* data, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t kPage = 4096;  // madvise wants a page-aligned start
  const auto begin = reinterpret_cast<std::uintptr_t>(data) / kPage * kPage;
  const auto end = reinterpret_cast<std::uintptr_t>(data) + bytes;
  if (bytes > 0) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);  // best effort
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace rayvec
