#pragma once

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace strata::view::detail {

/// Standard base64 (RFC 4648, with padding), as the page decodes it with atob().
std::string base64(std::string_view bytes);

/// zlib (RFC 1950) data of `bytes`, as the page inflates it with DecompressionStream("deflate").
std::string zlib_compress(std::string_view bytes);

/// The bytes of a vector of little-endian scalars (the page reads them as typed arrays).
template <class T>
std::string_view as_bytes(const std::vector<T>& values) {
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian data");
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

}  // namespace strata::view::detail
