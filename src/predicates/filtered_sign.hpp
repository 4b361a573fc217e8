#pragma once

// Exact signs of polynomials in the input coordinates (SPEC §2b). A predicate is written once as
// a generic lambda over a number type; it is evaluated first with ErrorBoundedDouble, a double
// carrying a rigorous bound on its rounding error, and only when that cannot decide the sign,
// again with GMP rationals, which are exact for double inputs.

#include <gmpxx.h>

#include <cmath>
#include <cstdint>

namespace strata::detail {

/// A double together with an upper bound of |value - exact value|. Inputs are exact (error 0).
/// Each operation adds the rounding error of its result (at most half an ulp, bounded by
/// |v| * 2^-53) and a tiny absolute term that covers underflow into subnormals.
struct ErrorBoundedDouble {
  double v = 0.0;
  double e = 0.0;

  ErrorBoundedDouble() = default;
  ErrorBoundedDouble(double value) : v(value), e(0.0) {}  // NOLINT: exact conversion by design
  ErrorBoundedDouble(double value, double error) : v(value), e(error) {}
};

inline constexpr double kUnitRoundoff = 0x1p-53;
inline constexpr double kUnderflowSlack = 0x1p-1000;

inline ErrorBoundedDouble operator+(ErrorBoundedDouble a, ErrorBoundedDouble b) {
  const double v = a.v + b.v;
  return {v, a.e + b.e + std::fabs(v) * kUnitRoundoff};
}
inline ErrorBoundedDouble operator-(ErrorBoundedDouble a, ErrorBoundedDouble b) {
  const double v = a.v - b.v;
  return {v, a.e + b.e + std::fabs(v) * kUnitRoundoff};
}
inline ErrorBoundedDouble operator*(ErrorBoundedDouble a, ErrorBoundedDouble b) {
  const double v = a.v * b.v;
  return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e +
                 std::fabs(v) * kUnitRoundoff + kUnderflowSlack};
}

/// The sign the filter can prove, or 2 when it cannot.
inline int certain_sign(const ErrorBoundedDouble& x) {
  // The bound itself was computed in floating point: inflate it so its own rounding (a few ulps
  // relative over a short chain of operations) cannot make it too small.
  const double bound = x.e * (1.0 + 0x1p-40) + kUnderflowSlack;
  if (x.v > bound) return 1;
  if (x.v < -bound) return -1;
  if (x.e == 0.0 && x.v == 0.0) return 0;
  return 2;
}

/// Counts, per thread, the decisions that needed exact arithmetic (for the report and tests).
inline std::uint64_t& exact_fallback_counter() {
  thread_local std::uint64_t counter = 0;
  return counter;
}

/// Sign of the polynomial computed by `expr`, a generic callable taking a type tag
/// (ErrorBoundedDouble or mpq_class) and returning a value of that type.
template <class Expr>
int filtered_sign(const Expr& expr) {
  const int s = certain_sign(expr(ErrorBoundedDouble{}));
  if (s != 2) return s;
  ++exact_fallback_counter();
  const mpq_class exact = expr(mpq_class{});
  return sgn(exact);
}

}  // namespace strata::detail
