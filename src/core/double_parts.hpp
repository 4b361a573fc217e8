#pragma once

#include <bit>
#include <cstdint>

namespace strata {

/// A finite double read from its bits: |x| = mantissa 2^exponent, the mantissa an integer of 53
/// bits for a normal x (its implicit leading bit set) and fewer below the normal range; 0 for
/// either zero. Exact integer arithmetic on doubles starts from it.
struct DoubleParts {
  std::uint64_t mantissa = 0;
  int exponent = 0;
  bool negative = false;
};

constexpr DoubleParts split_double(double x) {
  constexpr int kFractionBits = 52;
  constexpr int kExponentBias = 1023 + kFractionBits;  // of the integer mantissa
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased = static_cast<int>((bits >> kFractionBits) & 0x7FF);
  DoubleParts parts;
  parts.mantissa = bits & ((std::uint64_t{1} << kFractionBits) - 1);
  parts.exponent = 1 - kExponentBias;  // below the normal range: no implicit leading bit
  if (biased != 0) {
    parts.mantissa |= std::uint64_t{1} << kFractionBits;
    parts.exponent = biased - kExponentBias;
  }
  parts.negative = (bits >> 63) != 0;
  return parts;
}

}  // namespace strata
