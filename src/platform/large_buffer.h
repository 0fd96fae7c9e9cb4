// LargeBuffer: uninitialized, 64-byte aligned memory for the big arrays of a build (primitive
// records, the TriangleSoA blocks) and a render's framebuffer. From 2 MiB up it is 2 MiB aligned and advised
// for transparent huge pages (madvise MADV_HUGEPAGE, Linux), so the first touch of each 2 MiB takes one page
// fault instead of 512, and the ray kernels' random leaf accesses need far fewer TLB entries. Where the
// advice is refused (other kernels, THP off) it is ordinary memory; nothing depends on it.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <memory>

namespace rayvec {

struct LargeBufferFree {
  void operator()(void* p) const { std::free(p); }
};
using LargeBuffer = std::unique_ptr<void, LargeBufferFree>;

// At least `bytes` bytes (64 bytes for 0); throws std::bad_alloc when out of memory.
LargeBuffer allocate_large_buffer(std::size_t bytes);

// A std::vector allocator whose storage is allocate_large_buffer's: for arrays that are filled once
// and can be large (a framebuffer), so that their first touch takes huge-page faults.
template <class T>
struct LargeAllocator {
  using value_type = T;
  LargeAllocator() = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocate_large_buffer(n * sizeof(T)).release()); }
  void deallocate(T* p, std::size_t) { std::free(p); }
  friend bool operator==(LargeAllocator, LargeAllocator) { return true; }
};

// The same advice for memory allocated elsewhere and not touched yet (a reserved std::vector or
// std::string of 2 MiB and more): the whole 2 MiB pages inside [data, data + bytes). Loading a
// 39 MB OBJ spends about a third of its time in page faults without it.
void advise_huge_pages(const void* data, std::size_t bytes);

// Faults in the pages of [data, data + bytes) for writing, leaving their contents as they are
// (MADV_POPULATE_WRITE, Linux 5.14 on), so that the calling thread pays for the kernel's clearing of
// fresh pages instead of a later writer: lets a parallel phase prepare memory a serial one fills.
// Does nothing where the kernel lacks it.
void prefault_pages(const void* data, std::size_t bytes);

}  // namespace rayvec
