#pragma once

#include <cstddef>
#include <vector>

namespace strata {

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with transparent
/// huge pages, before they are first written, when the buffer is larger than 32 MiB (a mapping
/// of its own). A large buffer filled once (a model's file and facets) then costs one page fault
/// per 2 MiB rather than one per 4 KiB: reading and welding a million facets spent about half
/// its time in the kernel faulting pages in. Only a hint: where the kernel does not offer it,
/// nothing changes.
void advise_huge_pages(void* data, std::size_t bytes);

/// v.reserve(n), its new storage advised as above. Call it on an empty vector, before filling.
template <class T>
void reserve_huge_pages(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace strata
