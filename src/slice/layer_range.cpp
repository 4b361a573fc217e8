#include "strata/slice/layer_range.hpp"

#include <fmt/format.h>

#include <charconv>
#include <utility>

namespace strata {

namespace {

std::optional<std::uint32_t> parse_index(std::string_view text) {
  std::uint32_t value = 0;
  const char* last = text.data() + text.size();
  const auto parsed = std::from_chars(text.data(), last, value);
  if (text.empty() || parsed.ec != std::errc{} || parsed.ptr != last) return std::nullopt;
  return value;
}

Error usage(std::string message) { return Error{ErrorCode::Usage, std::move(message), {}}; }

}  // namespace

Result<LayerRange> parse_layer_range(std::string_view text) {
  const auto bad = [&] {
    return usage(fmt::format(
        "layer range '{}' is not A:B (layers A to B-1), A: (A to the last) or K (layer K)", text));
  };
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) {
    const auto k = parse_index(text);
    if (!k || *k == UINT32_MAX) return bad();
    return LayerRange{*k, *k + 1};
  }
  const auto first = parse_index(text.substr(0, colon));
  if (!first) return bad();
  const std::string_view tail = text.substr(colon + 1);
  if (tail.empty()) return LayerRange{*first, std::nullopt};
  const auto end = parse_index(tail);
  if (!end) return bad();
  if (*end <= *first) {
    return usage(
        fmt::format("layer range '{}' is empty: its end must be above its first layer", text));
  }
  return LayerRange{*first, *end};
}

Result<LayerSpan> resolve_layer_range(const LayerRange& range, std::uint32_t nz) {
  const std::uint32_t end = range.end.value_or(nz);
  if (range.first >= nz || end > nz) {
    return usage(fmt::format("layer range {}:{} reaches past the model's {} layers (0 to {})",
                             range.first, end, nz, nz - 1));
  }
  if (end <= range.first) {
    return usage(fmt::format("layer range {}:{} is empty", range.first, end));
  }
  return LayerSpan{range.first, end};
}

}  // namespace strata
