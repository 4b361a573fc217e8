// One decoding step in front of the text readers (ASCII STL, OBJ, OFF, PLY): they scan bytes as
// ASCII, so a file saved by a Windows tool as UTF-16 would otherwise read as a mesh of no lines
// they know ("no facets"), which sends the user the wrong way.
#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

Error encoding_error(std::string_view name, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::string(name)};
}

bool starts_with(std::string_view bytes, std::string_view prefix) {
  return bytes.substr(0, prefix.size()) == prefix;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

/// UTF-16 code units after the byte-order mark, to UTF-8.
Result<std::string> utf16_to_utf8(std::string_view units, bool big_endian, std::string_view name,
                                  std::string_view encoding) {
  if (units.size() % 2 != 0) {
    return encoding_error(name, fmt::format("{} text of an odd number of bytes ({}): the file is "
                                            "cut short or not UTF-16",
                                            encoding, units.size() + 2));
  }
  auto unit_at = [&](std::size_t i) {
    const auto first = static_cast<std::uint8_t>(units[i]);
    const auto second = static_cast<std::uint8_t>(units[i + 1]);
    return static_cast<std::uint16_t>(big_endian ? (first << 8) | second : (second << 8) | first);
  };
  std::string out;
  out.reserve(units.size() / 2);
  for (std::size_t i = 0; i < units.size(); i += 2) {
    const std::uint16_t unit = unit_at(i);
    const std::size_t byte = i + 2;  // offset in the file, after the 2-byte mark
    if (unit >= 0xD800 && unit <= 0xDBFF) {
      const std::uint16_t low = i + 3 < units.size() ? unit_at(i + 2) : 0;
      if (!(low >= 0xDC00 && low <= 0xDFFF)) {
        return encoding_error(
            name, fmt::format("invalid {}: a high surrogate without its low half at byte {}",
                              encoding, byte));
      }
      append_utf8(out, 0x10000 + ((std::uint32_t{unit} - 0xD800) << 10) + (low - 0xDC00));
      i += 2;
    } else if (unit >= 0xDC00 && unit <= 0xDFFF) {
      return encoding_error(
          name, fmt::format("invalid {}: a low surrogate without its high half at byte {}",
                            encoding, byte));
    } else {
      append_utf8(out, unit);
    }
  }
  return out;
}

/// True when the first bytes look like ASCII text with `width`-byte code units, the ASCII byte at
/// `ascii_at` of each unit and NUL bytes in the others: UTF-16 or UTF-32 without a mark.
bool looks_like_wide_ascii(std::string_view bytes, std::size_t width, std::size_t ascii_at) {
  constexpr std::size_t kSample = 512;
  const std::size_t units = std::min(bytes.size(), kSample) / width;
  if (units < 2) return false;
  for (std::size_t u = 0; u < units; ++u) {
    for (std::size_t b = 0; b < width; ++b) {
      const auto c = static_cast<unsigned char>(bytes[u * width + b]);
      if (b == ascii_at ? (c == 0 || c > 0x7F) : c != 0) return false;
    }
  }
  return true;
}

}  // namespace

Result<TextBytes> decode_text_encoding(std::string_view bytes, std::string_view name) {
  TextBytes text;
  // UTF-32 first: its little-endian mark begins with UTF-16's.
  if (starts_with(bytes, std::string_view("\xFF\xFE\x00\x00", 4)) ||
      starts_with(bytes, std::string_view("\x00\x00\xFE\xFF", 4))) {
    return encoding_error(name,
                          "the file is UTF-32 text (byte-order mark), which strata does not "
                          "read; save it as ASCII, UTF-8 or UTF-16");
  }
  if (starts_with(bytes, "\xEF\xBB\xBF")) {
    text.mark_bytes = 3;
    text.encoding = "UTF-8 with a byte-order mark";
    return text;
  }
  const bool little = starts_with(bytes, "\xFF\xFE");
  if (little || starts_with(bytes, "\xFE\xFF")) {
    text.encoding = little ? "UTF-16 LE" : "UTF-16 BE";
    Result<std::string> decoded = utf16_to_utf8(bytes.substr(2), !little, name, text.encoding);
    if (!decoded) return decoded.error();
    text.mark_bytes = 2;
    text.decoded = std::move(decoded).value();
    return text;
  }
  const struct {
    std::size_t width;
    std::size_t ascii_at;
    std::string_view encoding;
  } unmarked[] = {
      {4, 0, "UTF-32 LE"}, {4, 3, "UTF-32 BE"}, {2, 0, "UTF-16 LE"}, {2, 1, "UTF-16 BE"}};
  for (const auto& candidate : unmarked) {
    if (looks_like_wide_ascii(bytes, candidate.width, candidate.ascii_at)) {
      return encoding_error(
          name, fmt::format("the file looks like {} text without a byte-order mark (NUL bytes "
                            "between its characters); strata reads ASCII or UTF-8, and UTF-16 "
                            "with a byte-order mark: save it again in one of those",
                            candidate.encoding));
    }
  }
  return text;
}

}  // namespace strata::io::detail
