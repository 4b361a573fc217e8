#include "core/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace strata {

void advise_huge_pages(void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  // Only a buffer this large is sure to be a mapping of its own (glibc's malloc maps every
  // request above 32 MiB separately, whatever its adaptive threshold): the advice then ends
  // with the buffer. On a smaller one it could mark part of the heap, whose later tenants, a
  // layer's cells freed and allocated again, would each fault in and zero a whole 2 MiB page.
  constexpr std::size_t kOwnMapping = std::size_t{32} << 20;
  if (data == nullptr || bytes <= kOwnMapping) return;
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  // A refusal (no THP in this kernel) leaves ordinary pages: ignored.
  (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}  // namespace

void* map_zeroed_pages(std::size_t bytes) {
  // Below a huge page, a mapping of its own would gain nothing and cost two system calls.
  if (bytes < kHugePage) {
    void* data = std::calloc(bytes, 1);
    if (data == nullptr) throw std::bad_alloc();
    return data;
  }
  void* data = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (data == MAP_FAILED) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  // The mapping is the array's own: the advice ends with it. A refusal leaves ordinary pages.
  (void)madvise(data, bytes, MADV_HUGEPAGE);
#endif
  return data;
}

void unmap_pages(void* data, std::size_t bytes) {
  if (bytes < kHugePage) {
    std::free(data);
  } else {
    (void)munmap(data, bytes);
  }
}

}  // namespace strata
