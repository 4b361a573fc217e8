#include <fmt/compile.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "export/shortest_number_internal.hpp"

namespace strata::io::detail {
namespace {

/// "00" to "99", two characters a pair: the digits are written two at a time.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Writes the decimal digits of `n` ending just before `end`; returns where they begin.
char* write_digits_backwards(char* end, std::uint64_t n) {
  while (n >= 100) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * (n % 100), 2);
    n /= 100;
  }
  if (n >= 10) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * n, 2);
  } else {
    *--end = static_cast<char>('0' + n);
  }
  return end;
}

}  // namespace

char* write_shortest(char* out, double v) {
  if (!std::isfinite(v)) return fmt::format_to(out, FMT_COMPILE("{}"), v);
  if (std::signbit(v)) *out++ = '-';
  if (v == 0.0) {
    *out++ = '0';
    return out;
  }
  // The shortest digits that read back to v (fmt's Dragonbox, as "{}" uses), laid out as
  // fmt::format("{}") lays them out: fixed notation for decimal exponents -4 to 15, else
  // d.ddde±XX with at least two exponent digits.
  const auto decimal = fmt::detail::dragonbox::to_decimal(std::fabs(v));
  char digits[20];
  char* const digits_end = digits + sizeof digits;
  const char* first = write_digits_backwards(digits_end, decimal.significand);
  const auto count = static_cast<int>(digits_end - first);
  const int exponent = decimal.exponent;
  const int output_exponent = exponent + count - 1;
  if (output_exponent < -4 || output_exponent >= 16) {
    *out++ = first[0];
    if (count > 1) {
      *out++ = '.';
      std::memcpy(out, first + 1, static_cast<std::size_t>(count - 1));
      out += count - 1;
    }
    *out++ = 'e';
    *out++ = output_exponent < 0 ? '-' : '+';
    const auto magnitude = static_cast<std::uint64_t>(std::abs(output_exponent));
    if (magnitude < 10) *out++ = '0';
    char exponent_digits[4];
    const char* e = write_digits_backwards(exponent_digits + 4, magnitude);
    const auto length = static_cast<std::size_t>(exponent_digits + 4 - e);
    std::memcpy(out, e, length);
    return out + length;
  }
  if (exponent >= 0) {
    // 1234e2 -> 123400
    std::memcpy(out, first, static_cast<std::size_t>(count));
    out += count;
    std::memset(out, '0', static_cast<std::size_t>(exponent));
    return out + exponent;
  }
  const int integer_digits = count + exponent;
  if (integer_digits > 0) {
    // 1234e-2 -> 12.34
    std::memcpy(out, first, static_cast<std::size_t>(integer_digits));
    out += integer_digits;
    *out++ = '.';
    std::memcpy(out, first + integer_digits, static_cast<std::size_t>(-exponent));
    return out - exponent;
  }
  // 1234e-6 -> 0.001234
  *out++ = '0';
  *out++ = '.';
  std::memset(out, '0', static_cast<std::size_t>(-integer_digits));
  out -= integer_digits;
  std::memcpy(out, first, static_cast<std::size_t>(count));
  return out + count;
}

}  // namespace strata::io::detail
