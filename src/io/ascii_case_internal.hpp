#pragma once

// Case folding of ASCII only, as the formats define their keywords: the locale plays no part,
// and a byte outside A-Z is kept as it is.

#include <cstddef>
#include <string>
#include <string_view>

namespace strata::io::detail {

/// `c` in lower case when it is an ASCII capital, else `c`.
constexpr char lower_ascii(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// `text` with its ASCII capitals in lower case.
inline std::string lower_ascii(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = lower_ascii(c);
  return out;
}

/// True when `text` is `lower_word` (a keyword written in lower case), whatever its case.
constexpr bool iequals_ascii(std::string_view text, std::string_view lower_word) {
  if (text.size() != lower_word.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (lower_ascii(text[i]) != lower_word[i]) return false;
  }
  return true;
}

}  // namespace strata::io::detail
