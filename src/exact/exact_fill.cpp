#include <mpfr.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "exact/exact_fill_internal.hpp"
#include "predicates/filtered_sign.hpp"
#include "predicates/grid_search.hpp"
#include "strata/core/error.hpp"

namespace strata::exact::detail {
namespace {

struct ScanCrossing {
  std::uint32_t row = 0;
  std::uint32_t cells_left = 0;  ///< cells whose centre lies left of the crossing
  int weight = 0;
  double x = 0.0;  ///< the exact crossing rounded once
};

/// Orders a row's crossings as their exact x would: by the nearest double, then by the cells
/// they lie right of (exact, and non-decreasing in the exact x). Crossings equal in both have no
/// cell centre and no hatch between them, so their order does not matter.
bool before(const ScanCrossing& a, const ScanCrossing& b) {
  if (a.x != b.x) return a.x < b.x;
  return a.cells_left < b.cells_left;
}

/// The number of k in [0, n) for which `below(k)` holds, `below` holding on a prefix.
template <class Pred>
std::uint32_t count_prefix(std::uint32_t n, const Pred& below) {
  std::uint32_t lo = 0;
  std::uint32_t hi = n;
  while (lo < hi) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    if (below(mid)) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

/// The exact crossings of one facet with the scanlines of a layer, on integers. The crossing of
/// row y with the facet's plane at height z is
///   x = a.x - (n.y (y - a.y) + n.z (z - a.z)) / n.x,  n = (b - a) x (c - a),
/// the point where the row meets the facet's segment (n.x is not 0 for a segment that crosses
/// rows). With every input an integer times 2^E (E the smallest exponent among them; capital
/// letters for the values over 2^E, n in units of 2^2E):
///   x = 2^E (K - n.y Y) / n.x,  K = A.x n.x + n.y A.y - n.z (Z - A.z),
/// one product and one difference a row, then one correctly rounded MPFR division: no rational
/// reduced, nothing allocated once the scratch values have grown.
class RowCrossings {
 public:
  RowCrossings() {
    mpfr_init2(num_, 64);
    mpfr_init2(den_, 64);
    mpfr_init2(quotient_, 53);
  }
  ~RowCrossings() {
    mpfr_clear(num_);
    mpfr_clear(den_);
    mpfr_clear(quotient_);
  }
  RowCrossings(const RowCrossings&) = delete;
  RowCrossings& operator=(const RowCrossings&) = delete;

  /// The facet abc at height z, for rows whose y values have exponents of at least `e_rows`
  /// (ilogb(y) - 52 over the nonzero ones).
  void start(const Vec3& a, const Vec3& b, const Vec3& c, double z, int e_rows) {
    e_ = e_rows;
    for (const double v : {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, z})
      lower_to_last_bit(e_, v);
    set_scaled(ax_, a.x, e_);
    set_scaled(ay_, a.y, e_);
    set_scaled(az_, a.z, e_);
    set_scaled(t1_, b.y, e_);  // B.y - A.y
    t1_ -= ay_;
    set_scaled(t2_, c.z, e_);  // C.z - A.z
    t2_ -= az_;
    set_scaled(t3_, b.z, e_);  // B.z - A.z
    t3_ -= az_;
    set_scaled(t4_, c.y, e_);  // C.y - A.y
    t4_ -= ay_;
    nx_ = t1_ * t2_ - t3_ * t4_;
    set_scaled(t5_, b.x, e_);  // B.x - A.x
    t5_ -= ax_;
    set_scaled(t6_, c.x, e_);  // C.x - A.x
    t6_ -= ax_;
    ny_ = t3_ * t6_ - t5_ * t2_;
    nz_ = t5_ * t4_ - t1_ * t6_;
    set_scaled(t1_, z, e_);
    t1_ -= az_;
    k_ = ax_ * nx_ + ny_ * ay_ - nz_ * t1_;
    set_exact(den_, nx_);
  }

  /// The nearest double to the crossing of row y (ties to even), as round_to_double would give.
  double rounded(double y) {
    set_scaled(t1_, y, e_);
    x_ = k_ - ny_ * t1_;
    set_exact(num_, x_);
    mpfr_div(quotient_, num_, den_, MPFR_RNDN);
    if (mpfr_zero_p(quotient_)) return 0.0;
    mpfr_mul_2si(quotient_, quotient_, e_, MPFR_RNDN);  // exact: MPFR's exponent is unbounded
    if (mpfr_get_exp(quotient_) >= -1021) return mpfr_get_d(quotient_, MPFR_RNDN);
    // Below the normal doubles: the rational's own rounding, which rounds once there too.
    set_scaled_quotient(q_, x_, nx_, e_);
    return round_to_double(q_.get_mpq_t());
  }

  /// Sign of (x - d) for the crossing of the row last passed to rounded(), exact.
  int compare(double d) {
    // x - d = (X 2^E - d n.x) / n.x, on integers over 2^F, F = min(E, exponent of d).
    int f = e_;
    lower_to_last_bit(f, d);
    set_scaled(t1_, d, f);
    t1_ *= nx_;
    t2_ = x_;
    if (e_ > f) mpz_mul_2exp(t2_.get_mpz_t(), t2_.get_mpz_t(), static_cast<mp_bitcnt_t>(e_ - f));
    return sgn(t2_ - t1_) * sgn(nx_);
  }

 private:
  /// out = v exactly, its precision grown to v's bits.
  static void set_exact(mpfr_ptr out, const mpz_class& v) {
    const std::size_t bits = std::max<std::size_t>(mpz_sizeinbase(v.get_mpz_t(), 2), 2);
    if (static_cast<std::size_t>(mpfr_get_prec(out)) < bits) {
      mpfr_set_prec(out, static_cast<mpfr_prec_t>(bits));
    }
    mpfr_set_z(out, v.get_mpz_t(), MPFR_RNDN);  // exact: the precision holds every bit
  }

  int e_ = 0;
  mpz_class ax_, ay_, az_, nx_, ny_, nz_, k_, x_, t1_, t2_, t3_, t4_, t5_, t6_;
  mpq_class q_;
  mpfr_t num_, den_, quotient_;
};

/// The same crossings in doubles with a rigorous bound on their error (ErrorBoundedDouble): an
/// interval holding the exact x, enough to count the cells left of it when no cell centre lies
/// inside. Where one does, the exact crossing decides (RowCrossings).
class RowCrossingBounds {
 public:
  /// The facet abc at height z; false when the sign of n.x is not certain in doubles (then no
  /// row of the facet is decided here).
  bool start(const Vec3& a, const Vec3& b, const Vec3& c, double z) {
    using E = strata::detail::ErrorBoundedDouble;
    const E d1 = E(b.y) - E(a.y);
    const E d2 = E(c.z) - E(a.z);
    const E d3 = E(b.z) - E(a.z);
    const E d4 = E(c.y) - E(a.y);
    const E d5 = E(b.x) - E(a.x);
    const E d6 = E(c.x) - E(a.x);
    nx_ = d1 * d2 - d3 * d4;
    ny_ = d3 * d6 - d5 * d2;
    const E nz = d5 * d4 - d1 * d6;
    rest_ = nz * (E(z) - E(a.z));
    ax_ = a.x;
    ay_ = a.y;
    // n.x far from zero against its error: the quotient's bound below stays small and finite.
    return std::fabs(nx_.v) > 4.0 * nx_.e + strata::detail::kUnderflowSlack;
  }

  /// The number of cell centres left of the exact crossing of row y, when no centre lies within
  /// the crossing's interval; nullopt when one does (or the interval is not finite).
  std::optional<std::uint32_t> cells_left(double y, const GridSpec& grid) const {
    double lo = 0.0;
    double hi = 0.0;
    bounds(y, lo, hi);
    if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
    const std::uint32_t left = strata::detail::count_prefix(
        (lo - grid.x0) / grid.dx + 0.5, grid.nx, [&](std::uint32_t i) { return grid.xc(i) < lo; });
    if (left < grid.nx && grid.xc(left) <= hi) return std::nullopt;
    return left;
  }

 private:
  /// Doubles lo < hi with the exact crossing of row y strictly between them.
  void bounds(double y, double& lo, double& hi) const {
    using E = strata::detail::ErrorBoundedDouble;
    using strata::detail::kUnderflowSlack;
    using strata::detail::kUnitRoundoff;
    // x = a.x - (n.y (y - a.y) + n.z (z - a.z)) / n.x
    const E num = ny_ * (E(y) - E(ay_)) + rest_;
    const double q = num.v / nx_.v;
    // |N/D - N'/D'| <= (|N - N'| + |N'/D'| |D - D'|) / (|D'| - |D - D'|), and the division's own
    // rounding; |N'/D'| <= |q| (1 + u).
    const double abs_q = std::fabs(q) * (1.0 + 2.0 * kUnitRoundoff);
    const double q_error = (num.e + abs_q * nx_.e) / (std::fabs(nx_.v) - nx_.e) +
                           abs_q * kUnitRoundoff + kUnderflowSlack;
    const double x = ax_ - q;
    const double error = q_error + std::fabs(x) * kUnitRoundoff;
    // The bound was itself computed in doubles: inflated so its own rounding cannot shrink it,
    // and one step past each rounded end.
    const double bound = error * (1.0 + 0x1p-40) + kUnderflowSlack;
    lo = std::nextafter(x - bound, -HUGE_VAL);
    hi = std::nextafter(x + bound, HUGE_VAL);
  }

  strata::detail::ErrorBoundedDouble nx_, ny_, rest_;
  double ax_ = 0.0;
  double ay_ = 0.0;
};

/// Counts the comparisons of an exact value with a double that the nearest double left tied.
class TieCounter {
 public:
  int compare(const RoundedRational& q, double d) {
    if (q.rounded == d) ++ties_;
    return compare_with_double(q, d);
  }
  /// Sign of (x - d) for the crossing `row` last rounded to `rounded`.
  int compare(RowCrossings& row, double rounded, double d) {
    if (rounded < d) return -1;
    if (rounded > d) return 1;
    ++ties_;
    return row.compare(d);
  }
  std::uint64_t ties() const { return ties_; }

 private:
  std::uint64_t ties_ = 0;
};

bool is_inside(FillRule rule, long long winding, long long count) {
  return rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
}

/// Adds the row's solid cells and, when `hatches` is given, appends its hatches.
void fill_row(FillRule rule, const GridSpec& grid, std::vector<ScanCrossing>::iterator begin,
              std::vector<ScanCrossing>::iterator end, SolidRows& cells,
              std::vector<HatchSegment>* hatches) {
  std::sort(begin, end, before);
  long long winding = 0;
  long long count = 0;
  for (auto it = begin; it != end; ++it) {
    winding += it->weight;
    ++count;
  }
  // Left of every crossing a point sees all of them; each crossing passed leaves the sum. Cells
  // left of crossing t and right of crossing t-1 see the crossings t, t+1, ...
  std::uint32_t from = 0;
  double hatch_from = grid.x0;
  for (auto it = begin; it != end; ++it) {
    const bool inside = is_inside(rule, winding, count);
    if (it->cells_left > from) {
      if (inside) cells.add(it->row, from, it->cells_left);
      from = it->cells_left;
    }
    if (hatches != nullptr && inside && it->x > hatch_from) {
      if (!hatches->empty() && hatches->back().row == it->row &&
          hatches->back().x_end == hatch_from) {
        hatches->back().x_end = it->x;
      } else {
        hatches->push_back({it->row, hatch_from, it->x});
      }
    }
    hatch_from = std::max(hatch_from, it->x);
    winding -= it->weight;
    --count;
  }
}

}  // namespace

LayerFill fill_layer(const IndexedMesh& mesh, const ExactLayer& layer, const GridSpec& grid,
                     FillRule rule, double scan_offset_mm, bool want_hatches) {
  LayerFill out;
  out.layer = layer.layer;
  out.solid = SolidRows(grid.nx, grid.ny);
  TieCounter ties;
  const auto row_y = [&](std::uint32_t j) { return grid.yc(j) + scan_offset_mm; };
  // Rows whose scanline lies at or below y (a point on the scanline counts as above it).
  const auto rows_at_or_below = [&](const RoundedRational& y) {
    return count_prefix(grid.ny, [&](std::uint32_t j) { return ties.compare(y, row_y(j)) >= 0; });
  };

  std::vector<ScanCrossing> crossings;
  RowCrossings row_crossings;
  RowCrossingBounds bounds;
  for (const ExactSegment& s : layer.segments) {
    if (s.zero_length) continue;
    const std::uint32_t rows_start = rows_at_or_below(layer.start_of(s).y);
    const std::uint32_t rows_end = rows_at_or_below(layer.end_of(s).y);
    if (rows_start == rows_end) continue;
    // Rows [first, last) have exactly one end point strictly below their scanline.
    const std::uint32_t first = std::min(rows_start, rows_end);
    const std::uint32_t last = std::max(rows_start, rows_end);
    const int weight = rule == FillRule::EvenOdd ? 1 : s.normal_x_sign;
    // A facet's segment runs along ez x n, so it rises in y exactly when n.x > 0 (SPEC §2 and
    // layer_segments.hpp agree); a mismatch would be a broken cut, not bad input.
    STRATA_ASSERT((rows_end > rows_start) == (s.normal_x_sign > 0) && s.normal_x_sign != 0,
                  "segment direction disagrees with the facet normal");
    const auto& corners = mesh.triangles[s.facet];
    const Vec3& a = mesh.vertices[corners[0]];
    const Vec3& b = mesh.vertices[corners[1]];
    const Vec3& c = mesh.vertices[corners[2]];
    // Without hatches only the cells left of each crossing matter: an interval in doubles
    // counts them unless a cell centre lies inside it. Such a count ties no comparison the exact
    // way would make (the rounded crossing lies inside the interval too).
    const bool bounded = !want_hatches && bounds.start(a, b, c, layer.z_mm);
    bool started = false;
    for (std::uint32_t j = first; j < last; ++j) {
      ScanCrossing crossing;
      crossing.row = j;
      crossing.weight = weight;
      if (const auto left = bounded ? bounds.cells_left(row_y(j), grid) : std::nullopt) {
        crossing.cells_left = *left;
        crossings.push_back(crossing);
        continue;
      }
      if (!started) {
        int e_rows = INT_MAX;
        for (std::uint32_t r = first; r < last; ++r) lower_to_last_bit(e_rows, row_y(r));
        row_crossings.start(a, b, c, layer.z_mm, e_rows);
        started = true;
      }
      const double x = row_crossings.rounded(row_y(j));
      crossing.cells_left = count_prefix(
          grid.nx, [&](std::uint32_t i) { return ties.compare(row_crossings, x, grid.xc(i)) > 0; });
      // Crossings without hatches are ordered by the cells left of them alone.
      crossing.x = want_hatches ? x : 0.0;
      crossings.push_back(crossing);
    }
  }
  out.crossings = crossings.size();

  std::sort(crossings.begin(), crossings.end(),
            [](const ScanCrossing& a, const ScanCrossing& b) { return a.row < b.row; });
  for (auto begin = crossings.begin(); begin != crossings.end();) {
    auto end = begin;
    while (end != crossings.end() && end->row == begin->row) ++end;
    fill_row(rule, grid, begin, end, out.solid, want_hatches ? &out.hatches : nullptr);
    begin = end;
  }
  out.exact_fallbacks = ties.ties();
  return out;
}

}  // namespace strata::exact::detail
