#pragma once

// Grid searches shared by the slicing and fill stages.

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace strata::detail {

/// A first guess as an index in [0, n]: NaN and negative guesses give 0, guesses at or past n
/// give n, others their integer part.
inline std::uint32_t clamp_guess(double estimate, std::uint32_t n) {
  if (!(estimate > 0.0)) return 0;
  if (estimate >= static_cast<double>(n)) return n;
  return static_cast<std::uint32_t>(estimate);
}

/// A reference to a caller's predicate on indices, without ownership: what the slow path of
/// count_prefix takes, so that one copy of that path serves every caller.
class IndexPredicate {
 public:
  template <class F>
  explicit IndexPredicate(const F& f)
      : object_(&f), call_([](const void* o, std::uint32_t k) {
          return static_cast<bool>((*static_cast<const F*>(o))(k));
        }) {}
  bool operator()(std::uint32_t k) const { return call_(object_, k); }

 private:
  const void* object_;
  bool (*call_)(const void*, std::uint32_t);
};

/// The number of k in [0, n) with below(k) (true on a prefix), when the guess k0 is known to be
/// wrong: `beyond_guess` says the answer lies above k0 (below(k0) holds), otherwise it lies below
/// k0 (below(k0 - 1) fails). Gallops away from k0, then bisects: O(log |answer - k0|)
/// evaluations, so a poor guess never costs O(n).
inline std::uint32_t search_prefix(std::uint32_t k0, std::uint32_t n, bool beyond_guess,
                                   IndexPredicate below) {
  // Invariant: lo == -1 or below(lo); hi == n or !below(hi). The answer is in (lo, hi].
  std::int64_t lo = -1;
  std::int64_t hi = n;
  if (beyond_guess) {
    lo = k0;
    for (std::int64_t step = 1;; step *= 2) {
      hi = std::min(lo + step, std::int64_t{n});
      if (hi == n || !below(static_cast<std::uint32_t>(hi))) break;
      lo = hi;
    }
  } else {
    hi = std::int64_t{k0} - 1;
    for (std::int64_t step = 1;; step *= 2) {
      lo = std::max(hi - step, std::int64_t{-1});
      if (lo < 0 || below(static_cast<std::uint32_t>(lo))) break;
      hi = lo;
    }
  }
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    (below(static_cast<std::uint32_t>(mid)) ? lo : hi) = mid;
  }
  return static_cast<std::uint32_t>(hi);
}

/// The number of k in [0, n) whose value(k) satisfies `below(k)`, where `below` is true for a
/// prefix of [0, n) (monotone) and n >= 1 (a grid axis is never empty: make_grid). `estimate` is a
/// first guess (anything, NaN included, e.g. the rounding of an approximate answer); the exact
/// predicate checks it, so the answer is exact, and the cost is two evaluations when the guess is
/// right. A template, so that each caller's predicate is inlined into the check of the guess (one
/// function behind a function pointer measured 2.8 -> 5.0 ns a call with slice_float's plane
/// test); the check has no branch but its outcome, and the rare wrong guess goes to
/// search_prefix, one copy for every caller.
template <class Below>
std::uint32_t count_prefix(double estimate, std::uint32_t n, const Below& below) {
  const std::uint32_t k = clamp_guess(estimate, n);
  // The answer is k when below(k - 1) holds and below(k) fails, where an index past either end
  // of [0, n) is not tested (the probes are clamped into the range and their outcome masked).
  const bool beyond = static_cast<bool>(below(std::min(k, n - 1))) & (k < n);
  const bool before = !static_cast<bool>(below(std::max(k, 1u) - 1)) & (k > 0);
  if (beyond == before) return k;  // both false: monotone predicates never make both true
  return search_prefix(k, n, beyond, IndexPredicate(below));
}

}  // namespace strata::detail
