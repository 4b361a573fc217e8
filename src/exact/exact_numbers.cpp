#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

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

  /// The nearest double to num / den (ties to even) when it is a normal double or infinite;
  /// NaN below the normal range. @pre num is not zero, den > 0.
  double round_quotient(mpz_srcptr num, mpz_srcptr den) {
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
    const auto quotient_bits = static_cast<int>(mpz_sizeinbase(quotient_, 2));  // 55 or 56
    const int dropped = quotient_bits - 53;
    const std::uint64_t q = mpz_getlimbn(quotient_, 0);  // |quotient|: its 56 bits fit one limb
    std::uint64_t mantissa = q >> dropped;
    const std::uint64_t rest = q & ((std::uint64_t{1} << dropped) - 1);
    const std::uint64_t half = std::uint64_t{1} << (dropped - 1);
    if (rest > half || (rest == half && (below || (mantissa & 1) != 0))) ++mantissa;
    // The result is mantissa 2^(dropped - s): its leading bit at 2^(52 + dropped - s), or one
    // higher when rounding carried into 2^53.
    const long exponent = static_cast<long>(dropped) - s;
    const long leading = exponent + (mantissa == (std::uint64_t{1} << 53) ? 53 : 52);
    if (leading < -1022) return std::numeric_limits<double>::quiet_NaN();
    if (leading > 1023) return negative ? -HUGE_VAL : HUGE_VAL;
    const double magnitude = std::ldexp(static_cast<double>(mantissa), static_cast<int>(exponent));
    return negative ? -magnitude : magnitude;
  }

 private:
  mpz_t shifted_, quotient_, remainder_;
};

mpq_srcptr raw_of(const mpq_class& q) { return q.get_mpq_t(); }
#ifdef CGAL_USE_GMP
[[maybe_unused]] mpq_srcptr raw_of(const CGAL::Gmpq& q) { return q.mpq(); }
#endif

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

int compare_with_double(const RoundedRational& q, double d) {
  if (q.rounded < d) return -1;
  if (q.rounded > d) return 1;
  const Rational exact_d(d);
  if (q.exact < exact_d) return -1;
  if (exact_d < q.exact) return 1;
  return 0;
}

int compare_xy(const ExactPoint2& a, const ExactPoint2& b) {
  const auto cmp = [](const RoundedRational& u, const RoundedRational& v) {
    if (u.rounded < v.rounded) return -1;
    if (u.rounded > v.rounded) return 1;
    if (u.exact < v.exact) return -1;
    if (v.exact < u.exact) return 1;
    return 0;
  };
  const int cx = cmp(a.x, b.x);
  return cx != 0 ? cx : cmp(a.y, b.y);
}

}  // namespace strata::exact::detail
