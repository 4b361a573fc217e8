#pragma once

// Integers of a fixed number of 64-bit limbs, with just the arithmetic an exact sum of
// determinants needs: GMP's calls cost more than the arithmetic itself when every operand is
// a few limbs long, and a million facets make six million products of three coordinates.

#include <array>
#include <cstddef>
#include <cstdint>

namespace strata::diagnose::detail {

/// The compilers' 128-bit integer, for one limb's product or sum with its carry; __extension__
/// says it is meant (-Wpedantic).
__extension__ typedef unsigned __int128 UInt128;

/// An unsigned integer, least significant limb first.
template <std::size_t N>
using Limbs = std::array<std::uint64_t, N>;

/// A value as sign and magnitude.
template <std::size_t N>
struct SignedLimbs {
  Limbs<N> magnitude{};
  bool negative = false;
};

/// a b c, exact. @pre a b c < 2^192 (three mantissas of doubles, say).
inline Limbs<3> multiply(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  const UInt128 ab = static_cast<UInt128>(a) * b;
  const UInt128 low = static_cast<UInt128>(static_cast<std::uint64_t>(ab)) * c;
  const UInt128 high = static_cast<UInt128>(static_cast<std::uint64_t>(ab >> 64)) * c;
  const UInt128 middle = (low >> 64) + static_cast<std::uint64_t>(high);
  return {static_cast<std::uint64_t>(low), static_cast<std::uint64_t>(middle),
          static_cast<std::uint64_t>(high >> 64) + static_cast<std::uint64_t>(middle >> 64)};
}

/// acc += v modulo 2^(64 N) (two's complement when acc is read as signed). @pre M <= N.
template <std::size_t N, std::size_t M>
void add_to(Limbs<N>& acc, const Limbs<M>& v) {
  static_assert(M <= N);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const UInt128 t = static_cast<UInt128>(acc[i]) + (i < M ? v[i] : 0) + carry;
    acc[i] = static_cast<std::uint64_t>(t);
    carry = static_cast<std::uint64_t>(t >> 64);
  }
}

/// acc -= v modulo 2^(64 N). @pre M <= N.
template <std::size_t N, std::size_t M>
void subtract_from(Limbs<N>& acc, const Limbs<M>& v) {
  static_assert(M <= N);
  std::uint64_t borrow = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const std::uint64_t x = i < M ? v[i] : 0;
    const std::uint64_t d = acc[i] - x - borrow;
    borrow = (acc[i] < x || (acc[i] == x && borrow != 0)) ? 1 : 0;
    acc[i] = d;
  }
}

/// Whether a two's complement value is negative.
template <std::size_t N>
bool is_negative(const Limbs<N>& v) {
  return (v[N - 1] >> 63) != 0;
}

/// The sign and magnitude of a two's complement value. @pre it is not -2^(64 N - 1).
template <std::size_t N>
SignedLimbs<N> sign_and_magnitude(const Limbs<N>& v) {
  SignedLimbs<N> out{v, is_negative(v)};
  if (out.negative) {
    Limbs<N> negated{};
    subtract_from(negated, v);
    out.magnitude = negated;
  }
  return out;
}

/// A sum of signed products of three limbs, each shifted into place, modulo 2^(64 N). The carry
/// out of each product's four limbs is counted, not carried, so that adding a product costs the
/// same at any shift; and there is no branch on its sign (the signs of a determinant's terms
/// follow no pattern a predictor could learn).
template <std::size_t N>
class ShiftedProductSum {
 public:
  /// Adds (negative ? -v : v) 2^shift. @pre v 2^shift < 2^(64 N); at most 2^62 additions.
  void add(const Limbs<3>& v, unsigned shift, bool negative) {
    const unsigned limb = shift / 64;
    const unsigned bit = shift % 64;
    // (x >> 1) >> (63 - bit) is x >> (64 - bit), and 0 when bit is 0.
    const std::array<std::uint64_t, 4> shifted = {
        v[0] << bit, (v[1] << bit) | ((v[0] >> 1) >> (63 - bit)),
        (v[2] << bit) | ((v[1] >> 1) >> (63 - bit)), (v[2] >> 1) >> (63 - bit)};
    // -x is ~x + 1 over every limb: below the four, x's zeros become ones that the 1 carries
    // through; above them, ones, which are -2^(64 (limb + 4)).
    const std::uint64_t flip = negative ? ~std::uint64_t{0} : 0;
    std::uint64_t carry = negative ? 1 : 0;
    std::uint64_t* at = limbs_.data() + limb;
    for (std::size_t k = 0; k < 4; ++k) {
      const UInt128 t = static_cast<UInt128>(at[k]) + (shifted[k] ^ flip) + carry;
      at[k] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    carries_[limb] += static_cast<std::int64_t>(carry) - (negative ? 1 : 0);
  }

  /// The sum modulo 2^(64 N), as two's complement.
  Limbs<N> total() const {
    Limbs<N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = limbs_[i];
    for (std::size_t limb = 0; limb + 4 < N; ++limb) {
      const std::int64_t count = carries_[limb];
      const std::uint64_t extension = count < 0 ? ~std::uint64_t{0} : 0;
      std::uint64_t carry = 0;
      for (std::size_t i = limb + 4; i < N; ++i) {
        const UInt128 t = static_cast<UInt128>(out[i]) +
                          (i == limb + 4 ? static_cast<std::uint64_t>(count) : extension) + carry;
        out[i] = static_cast<std::uint64_t>(t);
        carry = static_cast<std::uint64_t>(t >> 64);
      }
    }
    return out;
  }

 private:
  Limbs<N + 3> limbs_{};                   ///< a product's four limbs start at most at N - 1
  std::array<std::int64_t, N> carries_{};  ///< carries_[k]: carries into limb k + 4
};

}  // namespace strata::diagnose::detail
