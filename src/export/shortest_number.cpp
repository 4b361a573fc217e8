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

/// Writes the decimal digits of `n` < 100,000,000 ending just before `end`; returns where they
/// begin. On 32 bits, two digits a step.
char* write_digits_backwards(char* end, std::uint32_t n) {
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

/// Writes the eight digits of `n` < 100,000,000, leading zeros included, ending just before
/// `end`; returns where they begin. Split in two halves of four digits first, so that the two
/// halves' pairs are computed side by side rather than one after the other.
char* write_eight_digits(char* end, std::uint32_t n) {
  const std::uint32_t high = n / 10000;
  const std::uint32_t low = n % 10000;
  std::memcpy(end - 8, kDigitPairs + 2 * (high / 100), 2);
  std::memcpy(end - 6, kDigitPairs + 2 * (high % 100), 2);
  std::memcpy(end - 4, kDigitPairs + 2 * (low / 100), 2);
  std::memcpy(end - 2, kDigitPairs + 2 * (low % 100), 2);
  return end - 8;
}

/// The same for any `n` (a double's shortest significand is below 10^17): eight digits at a time
/// split off, so that the pairs are made on 32 bits.
char* write_digits_backwards(char* end, std::uint64_t n) {
  constexpr std::uint64_t kEightDigits = 100'000'000;
  while (n >= kEightDigits) {
    end = write_eight_digits(end, static_cast<std::uint32_t>(n % kEightDigits));
    n /= kEightDigits;
  }
  return write_digits_backwards(end, static_cast<std::uint32_t>(n));
}

/// Copies kCopyBytes, a constant that the compiler turns into a few moves where a copy of the
/// exact length calls memcpy: what is copied past the text is overwritten or left past its end.
constexpr std::size_t kCopyBytes = 24;
void copy_ahead(char* to, const char* from) { std::memcpy(to, from, kCopyBytes); }

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
  // The digits end at kDigitsEnd and zeros follow them, so that a copy ahead from any digit
  // stays in the array, and one of an integer's digits brings its trailing zeros along.
  constexpr std::size_t kDigitsEnd = 20;
  char digits[kDigitsEnd + kCopyBytes + 4];
  std::memset(digits + kDigitsEnd, '0', sizeof digits - kDigitsEnd);
  const char* first = write_digits_backwards(digits + kDigitsEnd, decimal.significand);
  const auto count = static_cast<int>(digits + kDigitsEnd - first);
  const int exponent = decimal.exponent;
  const int output_exponent = exponent + count - 1;
  if (output_exponent < -4 || output_exponent >= 16) {
    *out++ = first[0];
    if (count > 1) {
      *out++ = '.';
      copy_ahead(out, first + 1);
      out += count - 1;
    }
    *out++ = 'e';
    *out++ = output_exponent < 0 ? '-' : '+';
    const int magnitude = std::abs(output_exponent);  // 5 to 324
    if (magnitude >= 100) *out++ = static_cast<char>('0' + magnitude / 100);
    std::memcpy(out, kDigitPairs + 2 * (magnitude % 100), 2);
    return out + 2;
  }
  if (exponent >= 0) {
    // 1234e2 -> 123400 (16 digits at most: the zeros follow the digits)
    copy_ahead(out, first);
    return out + count + exponent;
  }
  const int integer_digits = count + exponent;
  if (integer_digits > 0) {
    // 1234e-2 -> 12.34
    copy_ahead(out, first);
    out += integer_digits;
    *out++ = '.';
    copy_ahead(out, first + integer_digits);
    return out - exponent;
  }
  // 1234e-6 -> 0.001234 (three zeros after the point at most)
  std::memcpy(out, "0.000", 5);
  out += 2 - integer_digits;
  copy_ahead(out, first);
  return out + count;
}

}  // namespace strata::io::detail
