// The display mesh's flat map gives every key the index std::unordered_map would.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <unordered_map>

#include "view/flat_index_map_internal.hpp"

namespace strata::view::detail {
namespace {

struct IdentityHash {
  std::size_t operator()(std::uint64_t k) const { return k; }
};

/// Every key in one slot: each lookup probes past the keys stored before.
struct CollidingHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>&) const { return 0; }
};

TEST(FlatIndexMap, KeepsTheFirstIndexOfAKey) {
  FlatIndexMap<std::uint64_t, IdentityHash> map;
  const auto [first, inserted] = map.try_emplace(7, 3);
  EXPECT_TRUE(inserted);
  EXPECT_EQ(first, 3u);
  const auto [again, inserted_again] = map.try_emplace(7, 9);
  EXPECT_FALSE(inserted_again);
  EXPECT_EQ(again, 3u);
  EXPECT_EQ(map.size(), 1u);
}

TEST(FlatIndexMap, AgreesWithUnorderedMapOnRandomKeysWhileGrowing) {
  const std::uint32_t seed = 20261127;
  SCOPED_TRACE(::testing::Message() << "seed " << seed);
  std::mt19937_64 random(seed);
  // Few distinct keys among many draws, so that most lookups find a key stored before; keys
  // that differ in their high bits alone collide in a table that took the low bits.
  std::uniform_int_distribution<std::uint64_t> pick(0, 50'000);
  FlatIndexMap<std::uint64_t, IdentityHash> flat(16);
  std::unordered_map<std::uint64_t, std::uint32_t> reference;
  for (std::uint32_t n = 0; n < 200'000; ++n) {
    const std::uint64_t key = pick(random) << 40 | (pick(random) & 3);
    const auto [index, inserted] = flat.try_emplace(key, n);
    const auto [it, reference_inserted] = reference.try_emplace(key, n);
    ASSERT_EQ(inserted, reference_inserted) << "draw " << n;
    ASSERT_EQ(index, it->second) << "draw " << n;
  }
  EXPECT_EQ(flat.size(), reference.size());
}

TEST(FlatIndexMap, TellsApartKeysWhoseHashesCollide) {
  FlatIndexMap<std::array<std::uint32_t, 3>, CollidingHash> map;
  for (std::uint32_t n = 0; n < 100; ++n) {
    EXPECT_TRUE(map.try_emplace({n, n + 1, n + 2}, n).second) << n;
  }
  for (std::uint32_t n = 0; n < 100; ++n) {
    const auto [index, inserted] = map.try_emplace({n, n + 1, n + 2}, 1000);
    EXPECT_FALSE(inserted) << n;
    EXPECT_EQ(index, n);
  }
  EXPECT_EQ(map.size(), 100u);
}

}  // namespace
}  // namespace strata::view::detail
