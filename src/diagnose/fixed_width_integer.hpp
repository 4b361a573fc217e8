#pragma once

// Integers of a fixed number of 64-bit limbs, with just the arithmetic an exact sum of
// determinants needs: GMP's calls cost more than the arithmetic itself when every operand is
// two limbs long, and a million facets make ten million of them.

#include <array>
#include <cstddef>
#include <cstdint>

namespace strata::diagnose::detail {

/// An unsigned integer, least significant limb first.
template <std::size_t N>
using Limbs = std::array<std::uint64_t, N>;

/// A value as sign and magnitude.
template <std::size_t N>
struct SignedLimbs {
  Limbs<N> magnitude{};
  bool negative = false;
};

/// a b, exact.
template <std::size_t A, std::size_t B>
Limbs<A + B> multiply(const Limbs<A>& a, const Limbs<B>& b) {
  Limbs<A + B> out{};
  for (std::size_t i = 0; i < A; ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < B; ++j) {
      const unsigned __int128 t = static_cast<unsigned __int128>(a[i]) * b[j] + out[i + j] + carry;
      out[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    out[i + B] = carry;
  }
  return out;
}

/// acc += v modulo 2^(64 N) (two's complement when acc is read as signed). @pre M <= N.
template <std::size_t N, std::size_t M>
void add_to(Limbs<N>& acc, const Limbs<M>& v) {
  static_assert(M <= N);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const unsigned __int128 t = static_cast<unsigned __int128>(acc[i]) + (i < M ? v[i] : 0) + carry;
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

/// acc += (negative ? -v : v) modulo 2^(64 N).
template <std::size_t N, std::size_t M>
void add_signed(Limbs<N>& acc, const SignedLimbs<M>& v) {
  if (v.negative) {
    subtract_from(acc, v.magnitude);
  } else {
    add_to(acc, v.magnitude);
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

/// a b - c d as two's complement, exact when |a b - c d| < 2^(128 N - 1).
template <std::size_t N>
Limbs<2 * N> cross_difference(const SignedLimbs<N>& a, const SignedLimbs<N>& b,
                              const SignedLimbs<N>& c, const SignedLimbs<N>& d) {
  Limbs<2 * N> out{};
  add_signed(out, SignedLimbs<2 * N>{multiply(a.magnitude, b.magnitude), a.negative != b.negative});
  add_signed(out, SignedLimbs<2 * N>{multiply(c.magnitude, d.magnitude), c.negative == d.negative});
  return out;
}

/// acc += a m, m in two's complement.
template <std::size_t N, std::size_t A, std::size_t M>
void add_product(Limbs<N>& acc, const SignedLimbs<A>& a, const Limbs<M>& m) {
  const SignedLimbs<M> ms = sign_and_magnitude(m);
  add_signed(acc,
             SignedLimbs<A + M>{multiply(a.magnitude, ms.magnitude), a.negative != ms.negative});
}

}  // namespace strata::diagnose::detail
