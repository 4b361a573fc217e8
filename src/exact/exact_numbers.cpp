#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "exact/exact_numbers_internal.hpp"

namespace strata::exact::detail {
namespace {

/// Correct rounding for results below the normal range, where MPFR's 53-bit result would be
/// rounded a second time: mpq_get_d truncates towards zero, so the nearest double is d or its
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

/// A 53-bit MPFR value kept per thread, so rounding allocates nothing.
class Scratch {
 public:
  Scratch() { mpfr_init2(value_, 53); }
  ~Scratch() { mpfr_clear(value_); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  mpfr_ptr get() { return value_; }

 private:
  mpfr_t value_;
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
  mpfr_ptr r = scratch.get();
  // Correctly rounded to 53 bits with MPFR's unbounded exponent: exact as a double whenever the
  // result is a normal double (x = m 2^e with 1/2 <= |m| < 1: normal for e >= -1021).
  mpfr_set_q(r, q, MPFR_RNDN);
  if (mpfr_get_exp(r) < -1021) return round_small(q);
  return mpfr_get_d(r, MPFR_RNDN);
}

void set_scaled(mpz_class& out, double v, int e) {
  if (v == 0.0) {
    out = 0;
    return;
  }
  int exponent = 0;
  const double m = std::frexp(v, &exponent);  // v = m 2^exponent, 0.5 <= |m| < 1
  out = std::ldexp(m, 53);                    // an integer of at most 53 bits
  const int shift = exponent - 53 - e;        // >= 0 by the choice of e
  if (shift > 0) mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
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
