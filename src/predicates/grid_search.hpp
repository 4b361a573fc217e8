#pragma once

// Grid searches shared by the slicing and fill stages.

#include <cmath>
#include <cstdint>

namespace strata::detail {

/// The number of k in [0, n) whose value(k) satisfies `below(k)`, where `below` is true for a
/// prefix of [0, n) (monotone). `estimate` is a first guess (may be anything, e.g. NaN-free
/// rounding of an approximate answer); the exact predicate then walks from it, so the answer
/// is exact and the cost is O(1) when the guess is close.
/// A template, so that each caller's predicate is inlined into the walk: one function behind a
/// function pointer measured 2.8 -> 5.0 ns a call with slice_float's plane test (coverage then
/// counts the walk's branches once per caller).
template <class Below>
std::uint32_t count_prefix(double estimate, std::uint32_t n, const Below& below) {
  std::uint32_t k;
  if (!(estimate > 0.0)) {
    k = 0;
  } else if (estimate >= static_cast<double>(n)) {
    k = n;
  } else {
    k = static_cast<std::uint32_t>(estimate);
  }
  // Gallop when the guess is far off (a poor estimate must not cost O(n) steps).
  if (k > 0 && !below(k - 1)) {
    std::uint32_t hi = k - 1;  // !below(hi)
    std::uint32_t step = 1;
    std::uint32_t lo = hi;
    while (true) {
      if (lo == 0) break;
      lo = (lo > step) ? lo - step : 0;
      if (below(lo)) break;
      hi = lo;
      step *= 2;
    }
    if (lo == 0 && !below(0)) return 0;
    // below(lo) and !below(hi): binary search for the boundary.
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      (below(mid) ? lo : hi) = mid;
    }
    return hi;
  }
  if (k < n && below(k)) {
    std::uint32_t lo = k;  // below(lo)
    std::uint32_t step = 1;
    std::uint32_t hi = k;
    while (true) {
      hi = (n - lo > step) ? lo + step : n;
      if (hi == n || !below(hi)) break;
      lo = hi;
      step *= 2;
    }
    if (hi == n && below(n - 1)) return n;
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      (below(mid) ? lo : hi) = mid;
    }
    return hi;
  }
  return k;
}

}  // namespace strata::detail
