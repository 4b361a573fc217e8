#include <algorithm>
#include <cstdint>
#include <vector>

#include "exact/exact_fill_internal.hpp"
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

/// Counts the comparisons of an exact value with a double that the nearest double left tied.
class TieCounter {
 public:
  int compare(const RoundedRational& q, double d) {
    if (q.rounded == d) ++ties_;
    return compare_with_double(q, d);
  }
  /// Sign of (q - d) for q whose nearest double is `rounded`; `scratch` is reused.
  int compare(mpq_srcptr q, double rounded, double d, mpq_class& scratch) {
    if (rounded < d) return -1;
    if (rounded > d) return 1;
    ++ties_;
    scratch = d;
    return mpq_cmp(q, scratch.get_mpq_t());
  }
  std::uint64_t ties() const { return ties_; }

 private:
  std::uint64_t ties_ = 0;
};

bool is_inside(FillRule rule, long long winding, long long count) {
  return rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
}

void fill_row(FillRule rule, const GridSpec& grid, std::vector<ScanCrossing>::iterator begin,
              std::vector<ScanCrossing>::iterator end, std::uint8_t* cells,
              std::vector<HatchSegment>& hatches) {
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
      if (inside) std::fill(cells + from, cells + it->cells_left, std::uint8_t{1});
      from = it->cells_left;
    }
    if (inside && it->x > hatch_from) {
      if (!hatches.empty() && hatches.back().row == it->row && hatches.back().x_end == hatch_from) {
        hatches.back().x_end = it->x;
      } else {
        hatches.push_back({it->row, hatch_from, it->x});
      }
    }
    hatch_from = std::max(hatch_from, it->x);
    winding -= it->weight;
    --count;
  }
}

}  // namespace

LayerFill fill_layer(const ExactLayer& layer, const GridSpec& grid, FillRule rule,
                     double scan_offset_mm) {
  LayerFill out;
  out.layer = layer.layer;
  out.solid.assign(grid.cells_per_layer(), 0);
  TieCounter ties;
  const auto row_y = [&](std::uint32_t j) { return grid.yc(j) + scan_offset_mm; };
  // Rows whose scanline lies at or below y (a point on the scanline counts as above it).
  const auto rows_at_or_below = [&](const RoundedRational& y) {
    return count_prefix(grid.ny, [&](std::uint32_t j) { return ties.compare(y, row_y(j)) >= 0; });
  };

  std::vector<ScanCrossing> crossings;
  mpq_class y_row;
  mpq_class x_exact;
  mpq_class scratch;
  for (const ExactSegment& s : layer.segments) {
    if (s.zero_length) continue;
    const std::uint32_t rows_start = rows_at_or_below(s.start.y);
    const std::uint32_t rows_end = rows_at_or_below(s.end.y);
    if (rows_start == rows_end) continue;
    // Rows [first, last) have exactly one end point strictly below their scanline.
    const std::uint32_t first = std::min(rows_start, rows_end);
    const std::uint32_t last = std::max(rows_start, rows_end);
    const int weight = rule == FillRule::EvenOdd ? 1 : s.normal_x_sign;
    // A facet's segment runs along ez x n, so it rises in y exactly when n.x > 0 (SPEC §2 and
    // layer_segments.hpp agree); a mismatch would be a broken cut, not bad input.
    STRATA_ASSERT((rows_end > rows_start) == (s.normal_x_sign > 0) && s.normal_x_sign != 0,
                  "segment direction disagrees with the facet normal");
    // Along the segment x = a + b * y, with b = dx / dy: one multiplication and one addition a
    // row, in place, on scratch values that keep their storage.
    const Rational b = (s.end.x.exact - s.start.x.exact) / (s.end.y.exact - s.start.y.exact);
    const Rational a = s.start.x.exact - b * s.start.y.exact;
    for (std::uint32_t j = first; j < last; ++j) {
      y_row = row_y(j);
      mpq_mul(x_exact.get_mpq_t(), raw_mpq(b), y_row.get_mpq_t());
      mpq_add(x_exact.get_mpq_t(), x_exact.get_mpq_t(), raw_mpq(a));
      ScanCrossing c;
      c.row = j;
      c.weight = weight;
      c.x = round_to_double(x_exact.get_mpq_t());
      c.cells_left = count_prefix(grid.nx, [&](std::uint32_t i) {
        return ties.compare(x_exact.get_mpq_t(), c.x, grid.xc(i), scratch) > 0;
      });
      crossings.push_back(c);
    }
  }
  out.crossings = crossings.size();

  std::sort(crossings.begin(), crossings.end(),
            [](const ScanCrossing& a, const ScanCrossing& b) { return a.row < b.row; });
  for (auto begin = crossings.begin(); begin != crossings.end();) {
    auto end = begin;
    while (end != crossings.end() && end->row == begin->row) ++end;
    fill_row(rule, grid, begin, end, out.solid.data() + std::size_t{begin->row} * grid.nx,
             out.hatches);
    begin = end;
  }
  out.exact_fallbacks = ties.ties();
  return out;
}

}  // namespace strata::exact::detail
