#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#include "core/double_parts.hpp"
#include "exact/exact_numbers_internal.hpp"

namespace strata::exact::detail {
namespace {

/// Correct rounding for results below the normal range, where a 53-bit result would be rounded
/// a second time: mpq_get_d truncates towards zero, so the nearest double is d or its
/// neighbour away from zero, told apart by the exact midpoint. @pre q is not zero.
double round_small(mpq_srcptr q) {
  const mpq_class exact(q);
  const double d = mpq_get_d(q);
  const int s = sgn(exact);
  if (mpq_class(d) == exact) return d;
  const double away = std::nextafter(d, s > 0 ? HUGE_VAL : -HUGE_VAL);
  const mpq_class mid = (mpq_class(d) + mpq_class(away)) / 2;
  const int c = s > 0 ? cmp(exact, mid) : -cmp(exact, mid);
  if (c < 0) return d;
  if (c > 0) return away;
  std::int64_t bits = 0;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1) == 0 ? d : away;
}

/// The nearest double (ties to even) to +-(q + f) 2^scale, q an integer of 55 or 56 bits and
/// 0 <= f < 1 (f > 0 exactly when `below`), when it is a normal double or infinite; NaN below
/// the normal range.
double round_quotient_bits(std::uint64_t q, bool below, bool negative, long scale) {
  const int dropped = std::bit_width(q) - 53;  // 2 or 3: a rounding bit and at least one more
  std::uint64_t mantissa = q >> dropped;
  const std::uint64_t rest = q & ((std::uint64_t{1} << dropped) - 1);
  const std::uint64_t half = std::uint64_t{1} << (dropped - 1);
  if (rest > half || (rest == half && (below || (mantissa & 1) != 0))) ++mantissa;
  // The result is mantissa 2^(dropped + scale): its leading bit at 2^(52 + dropped + scale), or
  // one higher when rounding carried into 2^53.
  const long exponent = static_cast<long>(dropped) + scale;
  const long leading = exponent + (mantissa == (std::uint64_t{1} << 53) ? 53 : 52);
  if (leading < -1022) return std::numeric_limits<double>::quiet_NaN();
  if (leading > 1023) return negative ? -HUGE_VAL : HUGE_VAL;
  const double magnitude = std::ldexp(static_cast<double>(mantissa), static_cast<int>(exponent));
  return negative ? -magnitude : magnitude;
}

/// Integers kept per thread, so that rounding allocates nothing once they have grown.
class Scratch {
 public:
  Scratch() {
    mpz_init(shifted_);
    mpz_init(quotient_);
    mpz_init(remainder_);
  }
  ~Scratch() {
    mpz_clear(shifted_);
    mpz_clear(quotient_);
    mpz_clear(remainder_);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  /// The nearest double to 2^e num / den (ties to even) when it is a normal double or infinite;
  /// NaN below the normal range. @pre num is not zero, den > 0.
  double round_quotient(mpz_srcptr num, mpz_srcptr den, long e = 0) {
    // With s chosen so that |num| 2^s / den lies in (2^54, 2^56), its integer part has 55 or 56
    // bits: the 53 of the result, a rounding bit and at least one more; the remainder tells
    // whether anything lies below them.
    const long num_bits = static_cast<long>(mpz_sizeinbase(num, 2));
    const long den_bits = static_cast<long>(mpz_sizeinbase(den, 2));
    const long s = 55 - (num_bits - den_bits);
    if (s >= 0) {
      mpz_mul_2exp(shifted_, num, static_cast<mp_bitcnt_t>(s));
      mpz_tdiv_qr(quotient_, remainder_, shifted_, den);
    } else {
      mpz_mul_2exp(shifted_, den, static_cast<mp_bitcnt_t>(-s));
      mpz_tdiv_qr(quotient_, remainder_, num, shifted_);
    }
    const bool below = mpz_sgn(remainder_) != 0;
    const bool negative = mpz_sgn(quotient_) < 0;
    // |quotient|: its 56 bits fit one limb.
    return round_quotient_bits(mpz_getlimbn(quotient_, 0), below, negative, e - s);
  }

 private:
  mpz_t shifted_, quotient_, remainder_;
};

mpq_srcptr raw_of(const mpq_class& q) { return q.get_mpq_t(); }
#ifdef CGAL_USE_GMP
[[maybe_unused]] mpq_srcptr raw_of(const CGAL::Gmpq& q) { return q.mpq(); }
#endif

/// Exact crossing points, computed on integers: every double is an integer times a power of
/// two, so with all inputs of one edge scaled to the smallest exponent E,
///   x = 2^E (LX W + T (HX - LX)) / W,  W = HZ - LZ,  T = Z - LZ,
/// needs four integer operations a coordinate, then one division to round it, or one reduction
/// for the rational. Scratch values keep their storage from one point to the next.
class CrossingCalculator {
 public:
  /// The numerator of the crossing of the edge from lo (below z) to hi (above z) on `axis`; W
  /// and E are kept beside it.
  void start(const Vec3& lo, const Vec3& hi, double z, int axis) {
    e_ = std::numeric_limits<int>::max();
    for (const double v : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, z}) lower_to_last_bit(e_, v);
    set_scaled(lz_, lo.z, e_);
    set_scaled(w_, hi.z, e_);
    w_ -= lz_;
    set_scaled(t_, z, e_);
    t_ -= lz_;
    const double a = axis == 0 ? lo.x : lo.y;
    const double b = axis == 0 ? hi.x : hi.y;
    set_scaled(num_, a, e_);
    set_scaled(along_, b, e_);
    along_ -= num_;  // HX - LX
    along_ *= t_;    // T (HX - LX)
    num_ *= w_;      // LX W
    num_ += along_;  // numerator
  }

  double rounded(Scratch& scratch) const {
    if (sgn(num_) == 0) return 0.0;
    return scratch.round_quotient(num_.get_mpz_t(), w_.get_mpz_t(), e_);
  }
  void exact(Rational& out) const {
    mpq_class q;
    set_scaled_quotient(q, num_, w_, e_);
    out = Rational(q);
  }

 private:
  int e_ = 0;
  mpz_class lz_, w_, t_, num_, along_;
};

/// A double as an odd integer (or zero) times 2^exponent: trailing zero bits dropped, so a
/// float's value, or a small one beside large ones, scales to few bits.
DoubleParts odd_parts(double v) {
  DoubleParts parts = split_double(v);
  if (parts.mantissa != 0) {
    const int zeros = std::countr_zero(parts.mantissa);
    parts.mantissa >>= zeros;
    parts.exponent += zeros;
  }
  return parts;
}

/// v / 2^e when it has at most 62 bits (e at most v's exponent in odd_parts).
std::optional<std::int64_t> scaled_small(const DoubleParts& v, int e) {
  if (v.mantissa == 0) return 0;
  const int shift = v.exponent - e;
  if (shift > 62 - static_cast<int>(std::bit_width(v.mantissa))) return std::nullopt;
  const auto magnitude = static_cast<std::int64_t>(v.mantissa << shift);
  return v.negative ? -magnitude : magnitude;
}

// The compilers' 128-bit integers; __extension__ says they are meant (-Wpedantic).
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

int bit_width_128(UInt128 v) {
  const auto high = static_cast<std::uint64_t>(v >> 64);
  return high != 0 ? 64 + std::bit_width(high) : std::bit_width(static_cast<std::uint64_t>(v));
}

/// The crossing's nearest double (as CrossingCalculator::rounded) on 64- and 128-bit integers,
/// when every input over 2^E (E the least exponent of the five inputs' odd parts) fits 62 bits,
/// so that W, T and HX - LX fit 63 and the numerator 127: the usual case, the coordinates of a
/// mesh's floats and the plane's double spanning fewer than 62 bits. Nullopt otherwise.
std::optional<double> rounded_crossing_on_machine_integers(const Vec3& lo, const Vec3& hi, double z,
                                                           int axis) {
  const std::array<DoubleParts, 5> parts{odd_parts(lo.z), odd_parts(hi.z), odd_parts(z),
                                         odd_parts(axis == 0 ? lo.x : lo.y),
                                         odd_parts(axis == 0 ? hi.x : hi.y)};
  int e = std::numeric_limits<int>::max();
  for (const DoubleParts& p : parts) {
    if (p.mantissa != 0) e = std::min(e, p.exponent);
  }
  const auto lz = scaled_small(parts[0], e);
  const auto hz = scaled_small(parts[1], e);
  const auto zz = scaled_small(parts[2], e);
  const auto la = scaled_small(parts[3], e);
  const auto ha = scaled_small(parts[4], e);
  if (!lz || !hz || !zz || !la || !ha) return std::nullopt;
  const std::int64_t w = *hz - *lz;  // > 0: hi lies above the plane, lo below it
  const std::int64_t t = *zz - *lz;
  const std::int64_t d = *ha - *la;
  const Int128 n = static_cast<Int128>(*la) * w + static_cast<Int128>(t) * d;
  if (n == 0) return 0.0;
  const bool negative = n < 0;
  const UInt128 num = negative ? -static_cast<UInt128>(n) : static_cast<UInt128>(n);
  const auto den = static_cast<UInt128>(w);
  // As in Scratch::round_quotient: num 2^s / den in [2^54, 2^56). Shifted, num has 55 bits more
  // than den (at most 118), or den as many fewer than num (at most 72): both fit.
  const long s =
      55 - (bit_width_128(num) - static_cast<int>(std::bit_width(static_cast<std::uint64_t>(w))));
  UInt128 quotient = 0;
  UInt128 remainder = 0;
  if (s >= 0) {
    const UInt128 shifted = num << s;
    quotient = shifted / den;
    remainder = shifted % den;
  } else {
    const UInt128 shifted = den << -s;
    quotient = num / shifted;
    remainder = num % shifted;
  }
  return round_quotient_bits(static_cast<std::uint64_t>(quotient), remainder != 0, negative, e - s);
}

}  // namespace

mpq_srcptr raw_mpq(const Rational& q) { return raw_of(q); }

double round_to_double(mpq_srcptr q) {
  if (mpq_sgn(q) == 0) return 0.0;
  thread_local Scratch scratch;
  const double d = scratch.round_quotient(mpq_numref(q), mpq_denref(q));
  // Below the normal range a 53-bit rounding would be rounded a second time.
  return std::isnan(d) ? round_small(q) : d;
}

void set_scaled(mpz_class& out, double v, int e) {
  if (v == 0.0) {
    out = 0;
    return;
  }
  const DoubleParts parts = split_double(v);
  static_assert(sizeof(unsigned long) == sizeof(std::uint64_t), "a mantissa fits one limb");
  mpz_set_ui(out.get_mpz_t(), parts.mantissa);
  const int shift = parts.exponent - e;  // >= 0 by the choice of e
  if (shift > 0) mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
  if (parts.negative) mpz_neg(out.get_mpz_t(), out.get_mpz_t());
}

void set_scaled_quotient(mpq_class& out, const mpz_class& num, const mpz_class& den, int e) {
  mpq_set_num(out.get_mpq_t(), num.get_mpz_t());
  mpq_set_den(out.get_mpq_t(), den.get_mpz_t());
  mpq_canonicalize(out.get_mpq_t());
  if (e > 0) mpq_mul_2exp(out.get_mpq_t(), out.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  if (e < 0) mpq_div_2exp(out.get_mpq_t(), out.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
}

Rational exact_crossing(const Vec3& lo, const Vec3& hi, double z, int axis) {
  thread_local CrossingCalculator calculator;
  calculator.start(lo, hi, z, axis);
  Rational out;
  calculator.exact(out);
  return out;
}

double rounded_crossing(const Vec3& lo, const Vec3& hi, double z, int axis) {
  if (const std::optional<double> v = rounded_crossing_on_machine_integers(lo, hi, z, axis)) {
    return *v;
  }
  thread_local CrossingCalculator calculator;
  thread_local Scratch scratch;
  calculator.start(lo, hi, z, axis);
  return calculator.rounded(scratch);
}

int compare_with_double(const RoundedRational& q, double d) {
  return compare(q, RoundedRational::of_double(d));
}

int compare(const RoundedRational& u, const RoundedRational& v) {
  if (u.rounded < v.rounded) return -1;
  if (u.rounded > v.rounded) return 1;
  if (u.is_double() && v.is_double()) return 0;
  const int sign = cmp(u.exact(), v.exact());
  return (sign > 0) - (sign < 0);
}

int compare_xy(const ExactPoint2& a, const ExactPoint2& b) {
  const int cx = compare(a.x, b.x);
  return cx != 0 ? cx : compare(a.y, b.y);
}

}  // namespace strata::exact::detail
