#include "support/text_encodings.hpp"

#include <cstdint>
#include <stdexcept>

namespace strata::test {

std::string to_utf16(std::string_view text, Utf16Order order, bool with_mark) {
  std::string out;
  auto put = [&](std::uint16_t unit) {
    const auto high = static_cast<char>(unit >> 8);
    const auto low = static_cast<char>(unit & 0xFF);
    if (order == Utf16Order::BigEndian) {
      out += high;
      out += low;
    } else {
      out += low;
      out += high;
    }
  };
  if (with_mark) put(0xFEFF);
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    auto continuation = [&](std::size_t k) {
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) {
        throw std::invalid_argument("to_utf16: text is not UTF-8");
      }
      return static_cast<std::uint16_t>(static_cast<unsigned char>(text[i + k]) & 0x3F);
    };
    if (lead < 0x80) {
      put(lead);
      i += 1;
    } else if ((lead & 0xE0) == 0xC0) {
      put(static_cast<std::uint16_t>(((lead & 0x1F) << 6) | continuation(1)));
      i += 2;
    } else if ((lead & 0xF0) == 0xE0) {
      put(static_cast<std::uint16_t>(((lead & 0x0F) << 12) | (continuation(1) << 6) |
                                     continuation(2)));
      i += 3;
    } else {
      throw std::invalid_argument("to_utf16: only the Basic Multilingual Plane is encoded");
    }
  }
  return out;
}

}  // namespace strata::test
