#pragma once

#include <string>
#include <string_view>

namespace strata::test {

/// Byte orders of UTF-16 text.
enum class Utf16Order { LittleEndian, BigEndian };

/// `text` (ASCII or UTF-8 without surrogates beyond U+FFFF) as UTF-16 of `order`, with the
/// byte-order mark U+FEFF in front when `with_mark`: what a Windows editor saves as "Unicode".
/// Throws std::invalid_argument on bytes that are not UTF-8 of the Basic Multilingual Plane.
std::string to_utf16(std::string_view text, Utf16Order order, bool with_mark = true);

}  // namespace strata::test
