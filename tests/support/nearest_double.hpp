#pragma once

#include <gmpxx.h>
#include <mpfr.h>

namespace strata::test {

/// The nearest double to q (ties to even), by MPFR: the definition of one rounding that the
/// tests hold the library's own roundings to. For values in the normal range.
inline double nearest_double(const mpq_class& q) {
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

}  // namespace strata::test
