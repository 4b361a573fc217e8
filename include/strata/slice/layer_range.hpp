#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "strata/core/result.hpp"

namespace strata {

/// Which layers of the whole model's grid a run slices (SPEC §3.1b): the half-open range
/// [first, end), in layer indices of the whole grid; no `end` means up to the last layer.
struct LayerRange {
  std::uint32_t first = 0;
  std::optional<std::uint32_t> end;
};

/// A layer range resolved against a grid of nz layers: first < end <= nz.
struct LayerSpan {
  std::uint32_t first = 0;
  std::uint32_t end = 0;

  std::uint32_t count() const { return end - first; }
  bool contains(std::uint32_t k) const { return first <= k && k < end; }
  friend bool operator==(const LayerSpan&, const LayerSpan&) = default;
};

/// Reads "A:B" (layers A..B-1), "A:" (A to the last layer) or "K" (layer K alone).
/// @return Error{Usage} for any other text, or when B <= A.
Result<LayerRange> parse_layer_range(std::string_view text);

/// Resolves `range` against a grid of `nz` layers.
/// @return Error{Usage} when the range is empty or reaches past layer nz - 1.
Result<LayerSpan> resolve_layer_range(const LayerRange& range, std::uint32_t nz);

}  // namespace strata
