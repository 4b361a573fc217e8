#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
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

/// `bytes` of zeroed memory: from 2 MiB on, a mapping of its own advised to transparent huge
/// pages (for a table read at random that is too small for advise_huge_pages but beyond the TLB's
/// reach with 4 KiB pages); below, from the heap. Throws std::bad_alloc when the system refuses.
void* map_zeroed_pages(std::size_t bytes);
/// Returns what map_zeroed_pages gave for the same `bytes`.
void unmap_pages(void* data, std::size_t bytes);

/// An array of n zero-initialised T (all bits zero) in memory of its own (map_zeroed_pages),
/// returned to the system when it goes.
template <class T>
class ZeroedPageArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroedPageArray() = default;
  explicit ZeroedPageArray(std::size_t n)
      : data_(n == 0 ? nullptr : static_cast<T*>(map_zeroed_pages(n * sizeof(T)))), size_(n) {}
  ZeroedPageArray(ZeroedPageArray&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  ZeroedPageArray& operator=(ZeroedPageArray&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    return *this;
  }
  ZeroedPageArray(const ZeroedPageArray&) = delete;
  ZeroedPageArray& operator=(const ZeroedPageArray&) = delete;
  ~ZeroedPageArray() {
    if (data_ != nullptr) unmap_pages(data_, size_ * sizeof(T));
  }

  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace strata
