#pragma once

// What the text mesh readers (ASCII STL, OBJ) share: their lines, their vertex lines and how they
// quote input in messages.

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "io/read_mesh_internal.hpp"
#include "strata/core/result.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io::detail {

/// The physical lines of a text mesh file, one at a time, numbered from 1. A line ends at LF,
/// CRLF or a bare CR (all occur in the wild); reading stops at a line longer than the limit,
/// found without scanning past it.
class TextLines {
 public:
  TextLines(std::string_view text, std::size_t max_line_bytes)
      : text_(text), max_line_bytes_(max_line_bytes) {}

  /// Moves to the next line; false at the end of the text or on a line that is too long.
  bool next(std::string_view& line) {
    const std::size_t size = text_.size();
    if (pos_ >= size) return false;
    ++number_;
    const char* begin = text_.data() + pos_;
    const std::size_t available = size - pos_;
    const std::size_t window = std::min(available, max_line_bytes_ + 1);
    const char* end_of_window = begin + window;
    const char* eol = begin;
    while (eol < end_of_window && *eol != '\n' && *eol != '\r') ++eol;
    if (eol == end_of_window && available > max_line_bytes_) {
      too_long_ = true;
      return false;
    }
    line = std::string_view(begin, static_cast<std::size_t>(eol - begin));
    pos_ += line.size();
    if (pos_ < size) {
      const bool crlf = text_[pos_] == '\r' && pos_ + 1 < size && text_[pos_ + 1] == '\n';
      pos_ += crlf ? 2 : 1;
    }
    return true;
  }

  /// The number of the line read last (the long one when reading stopped at it).
  std::size_t number() const { return number_; }
  /// True when reading stopped at a line longer than the limit.
  bool too_long() const { return too_long_; }
  /// Leaves the rest of the text unread: next() returns false from now on.
  void skip_rest() { pos_ = text_.size(); }

 private:
  std::string_view text_;
  std::size_t max_line_bytes_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
  bool too_long_ = false;
};

/// Quotes a piece of input for a message, cut to `max_chars` and with control bytes written as
/// \xNN, so that a binary file read as text cannot fill a terminal with garbage.
inline std::string quote_input(std::string_view text, std::size_t max_chars) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < max_chars; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  if (text.size() > max_chars) out += "...";
  return out + "'";
}

/// The three coordinates a vertex line gives, taken from the start of `rest` and scanned as
/// `type` into `p`; what follows them is left in `rest`.
/// @param location  gives the place for a message (called only on an error)
/// @return Error{BadInput} at location() when there are fewer than three or one is a bad number
template <class Location>
Result<void> scan_vertex(std::string_view& rest, NumberType type, const Location& location,
                         std::array<double, 3>& p) {
  for (int k = 0; k < 3; ++k) {
    const std::string_view token = next_token(rest);
    if (token.empty()) {
      return Error{ErrorCode::BadInput,
                   fmt::format("vertex has {} coordinate{}, expected 3", k, k == 1 ? "" : "s"),
                   location()};
    }
    const ScannedNumber<double> scanned = scan_real(token, type);
    if (!scanned.ok()) return bad_number(location(), token, scanned);
    p[k] = scanned.value;
  }
  return {};
}

}  // namespace strata::io::detail
