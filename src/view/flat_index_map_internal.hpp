#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace strata::view::detail {

/// A map from keys to 32-bit indices in one flat array (open addressing, linear probing), for
/// the display mesh's groupings of a million vertices and facets, where std::unordered_map
/// allocates a node an entry and follows a pointer a lookup. Entries are only added.
/// @tparam Hash  a callable giving a key's 64-bit hash; its top bits choose the slot
template <class Key, class Hash>
class FlatIndexMap {
 public:
  /// An empty map with room for `expected` keys before it grows.
  explicit FlatIndexMap(std::size_t expected = 0) { rehash(slots_for(expected)); }

  /// The index of `key`: the one stored, or `index` stored now when the key is new (then true).
  /// The reference is valid until the next insertion. @pre index != 0xffffffff
  std::pair<std::uint32_t&, bool> try_emplace(const Key& key, std::uint32_t index) {
    if (2 * (size_ + 1) > slots_.size()) rehash(2 * slots_.size());
    for (std::size_t s = slot_of(key);; s = (s + 1) & mask_) {
      Slot& slot = slots_[s];
      if (slot.index == kEmpty) {
        slot = {key, index};
        ++size_;
        return {slot.index, true};
      }
      if (slot.key == key) return {slot.index, false};
    }
  }

  /// Keys stored.
  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;

  struct Slot {
    Key key{};
    std::uint32_t index = kEmpty;
  };

  /// A power of two at least twice `keys` (the table is kept at most half full).
  static std::size_t slots_for(std::size_t keys) { return std::bit_ceil(2 * keys + 2); }

  std::size_t slot_of(const Key& key) const {
    // Fibonacci hashing: the product's top bits depend on every bit of the hash.
    const std::uint64_t hash = Hash{}(key);
    return static_cast<std::size_t>((hash * 0x9e3779b97f4a7c15ULL) >> shift_);
  }

  void rehash(std::size_t slots) {
    const std::vector<Slot> old = std::exchange(slots_, std::vector<Slot>(slots));
    mask_ = slots - 1;
    shift_ = 64 - std::countr_zero(slots);
    for (const Slot& slot : old) {
      if (slot.index == kEmpty) continue;
      std::size_t s = slot_of(slot.key);
      while (slots_[s].index != kEmpty) s = (s + 1) & mask_;
      slots_[s] = slot;
    }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace strata::view::detail
