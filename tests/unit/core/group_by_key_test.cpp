// The threads' counting sort: items grouped by key in the sources' order, whatever the number of
// threads, against a stable sort of the same items.

#include "core/group_by_key.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace strata {
namespace {

/// What each source gives: none to three items, each a key and the item's own number.
struct Emitted {
  std::size_t source;
  std::uint32_t key;
  std::uint32_t item;
};

std::vector<Emitted> random_items(std::size_t sources, std::uint32_t keys, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<Emitted> out;
  for (std::size_t s = 0; s < sources; ++s) {
    const auto count = random() % 4;
    for (std::uint32_t i = 0; i < count; ++i) {
      out.push_back(
          {s, static_cast<std::uint32_t>(random() % keys), static_cast<std::uint32_t>(out.size())});
    }
  }
  return out;
}

/// The items grouped by key by group_by_key, with their starts.
template <class Count>
std::pair<std::vector<Count>, std::vector<std::uint32_t>> grouped(const std::vector<Emitted>& items,
                                                                  std::size_t sources,
                                                                  std::uint32_t keys) {
  // Each source's items, in the order it gives them.
  std::vector<std::size_t> first(sources + 1, 0);
  for (const Emitted& e : items) ++first[e.source + 1];
  for (std::size_t s = 0; s < sources; ++s) first[s + 1] += first[s];
  std::vector<std::uint32_t> out;
  auto start = group_by_key<Count>(
      keys, sources,
      [&](std::size_t s, auto&& visit) {
        for (std::size_t i = first[s]; i < first[s + 1]; ++i) visit(items[i].key, items[i].item);
      },
      [&](std::size_t total) {
        out.assign(total, 0xFFFFFFFFU);
        return out.data();
      });
  return {std::move(start), std::move(out)};
}

TEST(GroupByKey, GroupsEachKeysItemsInTheSourcesOrderWhateverTheNumberOfThreads) {
  // Enough sources for several ranges (65,536 a range at least), with keys some of which get no
  // item: fewer keys than sources, and as many (where the ranges are fewer, their counts being a
  // key each).
  constexpr std::size_t kSources = 300'000;
  for (const std::uint32_t keys : {50'000U, 300'000U}) {
    SCOPED_TRACE(keys);
    const std::vector<Emitted> items = random_items(kSources, keys, 7);
    std::vector<Emitted> expected = items;
    std::stable_sort(expected.begin(), expected.end(),
                     [](const Emitted& a, const Emitted& b) { return a.key < b.key; });
    for (const std::size_t threads : {1, 2, 3, 4}) {
      SCOPED_TRACE(threads);
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      const auto [start, out] = grouped<std::uint32_t>(items, kSources, keys);
      ASSERT_EQ(out.size(), items.size());
      ASSERT_EQ(start.size(), keys + 1U);
      for (std::size_t i = 0; i < out.size(); ++i) ASSERT_EQ(out[i], expected[i].item) << i;
      // Each key's items lie between its start and the next.
      std::size_t at = 0;
      for (std::uint32_t k = 0; k < keys; ++k) {
        ASSERT_EQ(start[k], at) << k;
        while (at < expected.size() && expected[at].key == k) ++at;
      }
      EXPECT_EQ(start[keys], items.size());
    }
  }
}

TEST(GroupByKey, TakesNoSourcesAndSourcesWithoutItems) {
  const auto [start, out] = grouped<std::size_t>({}, 0, 3);
  EXPECT_EQ(start, (std::vector<std::size_t>{0, 0, 0, 0}));
  EXPECT_TRUE(out.empty());
  // Sources that give nothing, then one item of the last key.
  const std::vector<Emitted> one{{4, 2, 0}};
  const auto [start_one, out_one] = grouped<std::size_t>(one, 5, 3);
  EXPECT_EQ(start_one, (std::vector<std::size_t>{0, 0, 0, 1}));
  EXPECT_EQ(out_one, (std::vector<std::uint32_t>{0}));
}

}  // namespace
}  // namespace strata
