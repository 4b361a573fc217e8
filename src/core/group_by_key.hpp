#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/usable_threads.hpp"

namespace strata {

/// Groups by key the items that emit(source, visit) gives for the sources 0 .. num_sources - 1
/// (visit(key, item) for each, key < num_keys, any number of times a source), each key's items in
/// the order the sources give them: a stable counting sort. `storage(total)` is called once, when
/// the items are counted, and returns where the `total` items go; the items of key k are placed
/// at [start[k], start[k + 1]) of it, start being what is returned (num_keys + 1 entries).
///
/// The sources are cut into one range a thread, each counting its items by key and then placing
/// them after those of the ranges before: the result does not depend on the number of threads.
/// Each range holds a count a key, so there are no more ranges than twice the sources a key: on
/// many threads the counts then take no more memory than two counts a source. `Count` holds any
/// count of items (std::uint32_t where they are fewer than 2^32: half the memory of a count).
template <class Count, class Emit, class Storage>
std::vector<Count> group_by_key(std::size_t num_keys, std::size_t num_sources, const Emit& emit,
                                const Storage& storage) {
  constexpr std::size_t kMinSourcesARange = 65536;
  const std::size_t threads = usable_threads();
  const std::size_t ranges =
      std::clamp<std::size_t>(std::min(num_sources / kMinSourcesARange,
                                       2 * num_sources / std::max<std::size_t>(num_keys, 1)),
                              1, threads);
  const auto sources_of = [&](std::size_t range) {
    return std::pair{num_sources * range / ranges, num_sources * (range + 1) / ranges};
  };
  // Each range's count of items a key, then where its next item of that key goes; each range
  // zeroes its own counts.
  std::vector<std::vector<Count>> next(ranges);
  tbb::parallel_for(std::size_t{0}, ranges, [&](std::size_t range) {
    std::vector<Count>& count = next[range];
    count.assign(num_keys, 0);
    const auto [begin, end] = sources_of(range);
    for (std::size_t s = begin; s < end; ++s)
      emit(s, [&](std::size_t key, const auto&) { ++count[key]; });
  });
  std::vector<Count> start(num_keys + 1);
  Count placed = 0;
  for (std::size_t k = 0; k < num_keys; ++k) {
    start[k] = placed;
    for (std::vector<Count>& at : next) placed += std::exchange(at[k], placed);
  }
  start[num_keys] = placed;
  const auto out = storage(static_cast<std::size_t>(placed));
  tbb::parallel_for(std::size_t{0}, ranges, [&](std::size_t range) {
    std::vector<Count>& at = next[range];
    const auto [begin, end] = sources_of(range);
    for (std::size_t s = begin; s < end; ++s) {
      emit(s, [&](std::size_t key, const auto& item) { out[at[key]++] = item; });
    }
  });
  return start;
}

}  // namespace strata
