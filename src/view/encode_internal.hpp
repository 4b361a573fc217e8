#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace strata::view::detail {

/// Standard base64 (RFC 4648, with padding), as the page decodes it with atob().
std::string base64(std::string_view bytes);

/// Characters the base64 of `bytes` bytes takes.
constexpr std::size_t base64_size(std::size_t bytes) { return (bytes + 2) / 3 * 4; }

/// Writes base64(bytes) at `to`, which has room for base64_size(bytes.size()) characters, with
/// no push_back a character (a large page holds tens of MB of it); returns the end.
char* write_base64(std::string_view bytes, char* to);

/// zlib (RFC 1950) data of `bytes`, as the page inflates it with DecompressionStream("deflate").
std::string zlib_compress(std::string_view bytes);

/// The bytes of a vector of little-endian scalars (the page reads them as typed arrays).
template <class T>
std::string_view as_bytes(const std::vector<T>& values) {
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian data");
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

}  // namespace strata::view::detail
