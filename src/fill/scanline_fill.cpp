#include "strata/fill/scanline_fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "predicates/crossing_predicates.hpp"
#include "predicates/grid_search.hpp"

namespace strata {

namespace {

/// One scanline crossing: it adds `weight` to cells [0, cells_left) of its row (the cells whose
/// centre lies left of the crossing), and sits at about x along the row (for hatches).
struct RowCrossing {
  std::uint32_t row;
  std::uint32_t cells_left;
  int weight;
  double x;
};

bool inside(FillRule rule, long long winding, long long count) {
  return rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
}

/// Adds the row's solid cells (when `cells` is given) and appends its hatches (when `hatches`
/// is given).
void emit_row(FillRule rule, const GridSpec& grid, std::uint32_t j, std::span<RowCrossing> row,
              SolidRows* cells, std::vector<HatchSegment>* hatches) {
  long long winding = 0;
  long long count = 0;
  for (const auto& c : row) {
    winding += c.weight;
    ++count;
  }
  long long w = winding;
  long long n = count;
  if (cells != nullptr) {
    // Cells: walk the crossings by the number of cells they lie right of; a cell's winding is
    // the sum over crossings still to its right.
    std::sort(row.begin(), row.end(), [](const RowCrossing& a, const RowCrossing& b) {
      return a.cells_left < b.cells_left;
    });
    std::uint32_t from = 0;
    for (const auto& c : row) {
      if (c.cells_left > from) {
        if (inside(rule, w, n)) cells->add(j, from, c.cells_left);
        from = c.cells_left;
      }
      w -= c.weight;
      --n;
    }
  }
  if (hatches == nullptr) return;
  // Hatches: the same sweep in continuous x, on the rounded crossing positions.
  std::sort(row.begin(), row.end(),
            [](const RowCrossing& a, const RowCrossing& b) { return a.x < b.x; });
  const double x_first = grid.x0;
  w = winding;
  n = count;
  double previous = x_first;
  for (const auto& c : row) {
    if (inside(rule, w, n) && c.x > previous) {
      if (!hatches->empty() && hatches->back().row == c.row && hatches->back().x_end == previous) {
        hatches->back().x_end = c.x;
      } else {
        hatches->push_back({c.row, previous, c.x});
      }
    }
    previous = std::max(previous, c.x);
    w -= c.weight;
    --n;
  }
}

/// The crossings ordered by row, by counting them a row (the rows are few, the crossings many).
/// Within a row they keep their order; what is made of a row does not depend on it (emit_row
/// sorts them, and ties add up the same in any order).
std::vector<RowCrossing> by_row(const std::vector<RowCrossing>& crossings) {
  if (crossings.empty()) return {};
  std::uint32_t lo = crossings.front().row;
  std::uint32_t hi = lo;
  for (const RowCrossing& c : crossings) {
    lo = std::min(lo, c.row);
    hi = std::max(hi, c.row);
  }
  std::vector<std::uint32_t> start(std::size_t{hi - lo} + 2, 0);
  for (const RowCrossing& c : crossings) ++start[c.row - lo + 1];
  for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
  std::vector<RowCrossing> sorted(crossings.size());
  for (const RowCrossing& c : crossings) sorted[start[c.row - lo]++] = c;
  return sorted;
}

/// Every crossing of layer `segments` with the rows' scanlines, weighted by sign(nx) of the facet
/// (or 1 when `unit_weights`), with the number of cells left of it decided exactly when
/// `want_cells` (0 otherwise).
std::vector<RowCrossing> collect_crossings(const IndexedMesh& mesh, const LayerSegments& segments,
                                           const GridSpec& grid, bool unit_weights,
                                           double scan_offset_mm, bool want_cells) {
  const double z = segments.z_mm;
  const auto row_y = [&](std::uint32_t j) { return grid.yc(j) + scan_offset_mm; };
  const double y_base = grid.y0 + scan_offset_mm;

  std::vector<RowCrossing> crossings;
  for (const LayerSegment& s : segments.segments) {
    const Vec3& p_lo = mesh.vertices[s.start_edge.below];
    const Vec3& p_hi = mesh.vertices[s.start_edge.above];
    const Vec3& q_lo = mesh.vertices[s.end_edge.below];
    const Vec3& q_hi = mesh.vertices[s.end_edge.above];
    // Rows whose scanline lies at or below each end point (a point on the line counts as above).
    const auto rows_below = [&](const Vec3& lo, const Vec3& hi, const Point2& approx) {
      return detail::count_prefix(
          (approx.y - y_base) / grid.dy + 0.5, grid.ny, [&](std::uint32_t j) {
            return detail::crossing_y_sign(lo, hi, z, row_y(j), approx.y) >= 0;
          });
    };
    const std::uint32_t rows_p = rows_below(p_lo, p_hi, s.start);
    const std::uint32_t rows_q = rows_below(q_lo, q_hi, s.end);
    if (rows_p == rows_q) continue;
    // In rows [first, last) exactly one end point is below the scanline.
    const bool q_is_above = rows_q > rows_p;
    const std::uint32_t first = std::min(rows_p, rows_q);
    const std::uint32_t last = std::max(rows_p, rows_q);
    const auto& t = mesh.triangles[s.facet];
    const int weight =
        unit_weights
            ? 1
            : detail::normal_x_sign(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    const Vec3& b_lo = q_is_above ? p_lo : q_lo;  // the end point below the scanline
    const Vec3& b_hi = q_is_above ? p_hi : q_hi;
    const Vec3& a_lo = q_is_above ? q_lo : p_lo;  // the end point on or above it
    const Vec3& a_hi = q_is_above ? q_hi : p_hi;
    const Point2 below = q_is_above ? s.start : s.end;
    const Point2 above = q_is_above ? s.end : s.start;
    const double dy_seg = above.y - below.y;
    for (std::uint32_t j = first; j < last; ++j) {
      const double yr = row_y(j);
      double x = below.x;
      if (dy_seg != 0.0) x = below.x + (yr - below.y) * (above.x - below.x) / dy_seg;
      std::uint32_t cells_left = 0;
      if (want_cells) {
        // Cell i is left of the crossing when its centre is; the segment's rounded end points
        // settle most centres.
        const detail::RoundedScanlineCrossing rounded(b_lo, b_hi, below, a_lo, a_hi, above, yr);
        const auto centre_left = [&](std::uint32_t i) {
          return detail::scanline_crossing_x_sign(b_lo, b_hi, a_lo, a_hi, z, yr, grid.xc(i),
                                                  rounded) > 0;
        };
        cells_left = detail::count_prefix((x - grid.x0) / grid.dx + 0.5, grid.nx, centre_left);
      }
      crossings.push_back({j, cells_left, weight, x});
    }
  }
  return by_row(crossings);
}

/// Calls visit(row, crossings of the row) for every row with crossings, in increasing row order.
template <typename Visit>
void for_each_row(std::vector<RowCrossing>& crossings, Visit&& visit) {
  for (std::size_t begin = 0; begin < crossings.size();) {
    std::size_t end = begin;
    while (end < crossings.size() && crossings[end].row == crossings[begin].row) ++end;
    visit(crossings[begin].row, std::span<RowCrossing>(crossings.data() + begin, end - begin));
    begin = end;
  }
}

}  // namespace

LayerFill scanline_fill(const IndexedMesh& mesh, const LayerSegments& segments,
                        const GridSpec& grid, FillRule rule, double scan_offset_mm,
                        FillWanted wanted) {
  const std::uint64_t fallbacks_before = detail::exact_fallback_counter();
  LayerFill out;
  out.layer = segments.layer;
  if (wanted.cells) out.solid = SolidRows(grid.nx, grid.ny);
  std::vector<RowCrossing> crossings = collect_crossings(
      mesh, segments, grid, rule == FillRule::EvenOdd, scan_offset_mm, wanted.cells);
  out.crossings = crossings.size();

  for_each_row(crossings, [&](std::uint32_t row, std::span<RowCrossing> in_row) {
    emit_row(rule, grid, row, in_row, wanted.cells ? &out.solid : nullptr,
             wanted.hatches ? &out.hatches : nullptr);
  });
  out.exact_fallbacks = detail::exact_fallback_counter() - fallbacks_before;
  return out;
}

std::vector<std::int32_t> scanline_winding_numbers(const IndexedMesh& mesh,
                                                   const LayerSegments& segments,
                                                   const GridSpec& grid, double scan_offset_mm) {
  std::vector<std::int32_t> winding(grid.cells_per_layer(), 0);
  std::vector<RowCrossing> crossings =
      collect_crossings(mesh, segments, grid, false, scan_offset_mm, true);
  for_each_row(crossings, [&](std::uint32_t row, std::span<RowCrossing> in_row) {
    // A crossing adds its weight to the cells left of it: a difference array, then a suffix sum.
    std::int32_t* cells = winding.data() + std::size_t{row} * grid.nx;
    std::vector<std::int64_t> added(std::size_t{grid.nx} + 1, 0);
    for (const RowCrossing& c : in_row) added[c.cells_left] += c.weight;
    std::int64_t sum = 0;
    for (std::uint32_t i = grid.nx; i-- > 0;) {
      sum += added[i + 1];
      cells[i] = static_cast<std::int32_t>(sum);
    }
  });
  return winding;
}

}  // namespace strata
