// The one number scanner of the text formats (issue 18): ASCII STL, OBJ, OFF, ASCII PLY and
// ASCII cells files read every number through it, so one token means the same value, or the same
// refusal, in every format.
#include "strata/io/scan_number.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "io/ascii_case_internal.hpp"

namespace strata::io {
namespace {

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }

using detail::iequals_ascii;
using detail::lower_ascii;

/// Where the parts of a token that follows the grammar are.
struct Shape {
  bool valid = false;
  bool negative = false;
  bool has_point = false;
  bool has_exponent = false;
  std::string_view unsigned_part;  ///< the token without its sign
};

Shape shape_of(std::string_view token) {
  Shape shape;
  std::size_t i = 0;
  const std::size_t n = token.size();
  if (i < n && (token[i] == '+' || token[i] == '-')) {
    shape.negative = token[i] == '-';
    ++i;
  }
  shape.unsigned_part = token.substr(i);
  std::size_t digits = 0;
  for (; i < n && is_digit(token[i]); ++i) ++digits;
  if (i < n && token[i] == '.') {
    shape.has_point = true;
    for (++i; i < n && is_digit(token[i]); ++i) ++digits;
  }
  if (digits == 0) return shape;
  if (i < n && (token[i] == 'e' || token[i] == 'E')) {
    shape.has_exponent = true;
    ++i;
    if (i < n && (token[i] == '+' || token[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    for (; i < n && is_digit(token[i]); ++i) ++exponent_digits;
    if (exponent_digits == 0) return shape;
  }
  shape.valid = i == n;
  return shape;
}

/// Why a token that does not follow the grammar is refused: the words and prefixes that other
/// parsers (strtod, from_chars) would accept get their own reason.
NumberFault fault_of_non_number(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  if (iequals_ascii(token, "inf") || iequals_ascii(token, "infinity") ||
      iequals_ascii(token, "nan") ||
      (token.size() >= 4 && iequals_ascii(token.substr(0, 4), "nan("))) {
    return NumberFault::NonFiniteWord;
  }
  if (token.size() >= 2 && token[0] == '0' && lower_ascii(token[1]) == 'x') {
    return NumberFault::Hexadecimal;
  }
  return NumberFault::NotANumber;
}

/// True when the magnitude of a token of valid shape is at least 1, from its digits and exponent
/// alone; decides whether from_chars' result_out_of_range was an overflow (at 1e308 and beyond)
/// or an underflow (below 1e-323). @pre the token's mantissa has a non-zero digit.
bool magnitude_at_least_one(std::string_view unsigned_part) {
  std::size_t i = 0;
  bool found = false;
  std::int64_t leading = 0;  // the decimal exponent of the first non-zero digit
  while (i < unsigned_part.size() && is_digit(unsigned_part[i])) {
    if (found) {
      ++leading;
    } else if (unsigned_part[i] != '0') {
      found = true;
    }
    ++i;
  }
  if (i < unsigned_part.size() && unsigned_part[i] == '.') {
    ++i;
    std::int64_t position = 0;
    while (i < unsigned_part.size() && is_digit(unsigned_part[i])) {
      ++position;
      if (!found && unsigned_part[i] != '0') {
        found = true;
        leading = -position;
      }
      ++i;
    }
  }
  std::int64_t exponent = 0;
  if (i < unsigned_part.size()) {  // 'e' or 'E'
    ++i;
    bool negative = false;
    if (unsigned_part[i] == '+' || unsigned_part[i] == '-') negative = unsigned_part[i++] == '-';
    // Saturates far beyond any double's exponent, and far beyond a token's digit count.
    constexpr std::int64_t kCap = std::int64_t{1} << 40;
    for (; i < unsigned_part.size(); ++i) {
      if (exponent < kCap) exponent = exponent * 10 + (unsigned_part[i] - '0');
    }
    if (negative) exponent = -exponent;
  }
  return leading + exponent >= 0;
}

struct IntegerRange {
  bool is_signed;
  std::uint64_t max;           ///< the largest value
  std::uint64_t max_negative;  ///< the magnitude of the smallest value (0 when unsigned)
  const char* name;
};

IntegerRange range_of(NumberType type) {
  switch (type) {
    case NumberType::Int8:
      return {true, 127, 128, "an 8-bit integer (-128 to 127)"};
    case NumberType::UInt8:
      return {false, 255, 0, "an unsigned 8-bit integer (0 to 255)"};
    case NumberType::Int16:
      return {true, 32767, 32768, "a 16-bit integer (-32768 to 32767)"};
    case NumberType::UInt16:
      return {false, 65535, 0, "an unsigned 16-bit integer (0 to 65535)"};
    case NumberType::Int32:
      return {true, 2147483647, 2147483648, "a 32-bit integer (-2147483648 to 2147483647)"};
    case NumberType::UInt32:
      return {false, 4294967295, 0, "an unsigned 32-bit integer (0 to 4294967295)"};
    case NumberType::Int64:
      return {true, std::uint64_t{9223372036854775807}, std::uint64_t{9223372036854775808u},
              "a 64-bit integer (-9223372036854775808 to 9223372036854775807)"};
    case NumberType::UInt64:
    case NumberType::Float64:
    case NumberType::Float32:
      break;
  }
  return {false, std::numeric_limits<std::uint64_t>::max(), 0,
          "an unsigned 64-bit integer (0 to 18446744073709551615)"};
}

bool is_integer_type(NumberType type) {
  return type != NumberType::Float64 && type != NumberType::Float32;
}

/// The sign and magnitude of an integer token, checked against the range of `type`.
struct IntegerScan {
  NumberFault fault = NumberFault::None;
  bool negative = false;
  std::uint64_t magnitude = 0;
};

IntegerScan scan_integer(std::string_view token, NumberType type) {
  IntegerScan scan;
  const Shape shape = shape_of(token);
  if (!shape.valid) {
    scan.fault = fault_of_non_number(token);
    return scan;
  }
  if (shape.has_point || shape.has_exponent) {
    scan.fault = NumberFault::NotAnInteger;
    return scan;
  }
  const char* begin = shape.unsigned_part.data();
  const char* end = begin + shape.unsigned_part.size();
  const auto [ptr, ec] = std::from_chars(begin, end, scan.magnitude);
  if (ec == std::errc::result_out_of_range) {
    scan.fault = NumberFault::OutOfRange;
    return scan;
  }
  if (ec != std::errc() || ptr != end) {
    scan.fault = NumberFault::NotANumber;  // unreachable once the shape is valid
    return scan;
  }
  scan.negative = shape.negative && scan.magnitude != 0;  // -0 is 0 in every type
  const IntegerRange range = range_of(type);
  if (scan.magnitude > (scan.negative ? range.max_negative : range.max)) {
    scan.fault = NumberFault::OutOfRange;
  }
  return scan;
}

/// The token as a message shows it: control bytes as \xNN, cut short after 40 characters.
std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxChars = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxChars; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c >= 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  if (token.size() > kMaxChars) out += "...";
  return out + "'";
}

}  // namespace

ScannedNumber<double> scan_real(std::string_view token, NumberType type) {
  ScannedNumber<double> out;
  out.type = type == NumberType::Float32 ? NumberType::Float32 : NumberType::Float64;
  const Shape shape = shape_of(token);
  if (!shape.valid) {
    out.fault = fault_of_non_number(token);
    return out;
  }
  // from_chars takes no '+'; it takes a '-', so only a '+' is cut off.
  const char* begin = token.data() + (token.front() == '+' ? 1 : 0);
  const char* end = token.data() + token.size();
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, end, value, std::chars_format::general);
  if (ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range)) {
    out.fault = NumberFault::NotANumber;  // unreachable once the shape is valid
    return out;
  }
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves the value untouched when the result rounds to zero or to infinity.
    if (magnitude_at_least_one(shape.unsigned_part)) {
      out.fault = NumberFault::TooLarge;
      return out;
    }
    value = shape.negative ? -0.0 : 0.0;
  }
  if (!std::isfinite(value)) {
    out.fault = NumberFault::TooLarge;
    return out;
  }
  if (out.type == NumberType::Float32) {
    // Round to nearest gives infinity from FLT_MAX + half an ulp (2^128 - 2^103) up; checked
    // before the cast, which C++ leaves undefined out of range.
    if (std::fabs(value) >= 0x1.ffffffp127) {
      out.fault = NumberFault::TooLarge;
      return out;
    }
    value = static_cast<double>(static_cast<float>(value));
  }
  out.value = value;
  return out;
}

ScannedNumber<std::int64_t> scan_signed(std::string_view token, NumberType type) {
  ScannedNumber<std::int64_t> out;
  out.type = type;
  if (!is_integer_type(type) || !range_of(type).is_signed) type = NumberType::Int64;
  const IntegerScan scan = scan_integer(token, type);
  out.fault = scan.fault;
  if (scan.fault != NumberFault::None) return out;
  // The magnitude is at most 2^63 when negative, 2^63 - 1 when not: no overflow below.
  out.value = scan.negative ? static_cast<std::int64_t>(0 - scan.magnitude)
                            : static_cast<std::int64_t>(scan.magnitude);
  return out;
}

ScannedNumber<std::uint64_t> scan_unsigned(std::string_view token, NumberType type) {
  ScannedNumber<std::uint64_t> out;
  out.type = type;
  if (!is_integer_type(type) || range_of(type).is_signed) type = NumberType::UInt64;
  const IntegerScan scan = scan_integer(token, type);
  out.fault = scan.fault;
  if (scan.fault == NumberFault::None) out.value = scan.magnitude;
  return out;
}

std::string bad_number_message(std::string_view token, NumberFault fault, NumberType type) {
  std::string why;
  switch (fault) {
    case NumberFault::None:
    case NumberFault::NotANumber:
      why = "not a number";
      break;
    case NumberFault::NonFiniteWord:
      why = "not a number (inf and nan are not accepted)";
      break;
    case NumberFault::Hexadecimal:
      why = "not a number (hexadecimal is not accepted)";
      break;
    case NumberFault::NotAnInteger:
      why = "not an integer (no decimal point or exponent where an integer is expected)";
      break;
    case NumberFault::TooLarge:
      why = type == NumberType::Float32 ? "too large for a float32 (|x| <= 3.4028235e38)"
                                        : "too large for a double (|x| <= 1.7976931348623157e308)";
      break;
    case NumberFault::OutOfRange:
      why = fmt::format("out of range for {}", range_of(type).name);
      break;
  }
  return fmt::format("bad number {}: {}", quoted(token), why);
}

Error bad_number(std::string location, std::string_view token, NumberFault fault, NumberType type) {
  return Error{ErrorCode::BadInput, bad_number_message(token, fault, type), std::move(location)};
}

}  // namespace strata::io
