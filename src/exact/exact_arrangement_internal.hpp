#pragma once

#include <cstdint>
#include <vector>

#include "exact/exact_numbers_internal.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::exact::detail {

/// The contours of a layer from the exact 2D arrangement of its segments.
struct ArrangementContours {
  std::vector<ExactLoop> loops;   ///< closed, inside on the left: outer CCW, holes CW
  std::uint32_t open_chains = 0;  ///< chain starts: segment ends with more out than in
};

/// Inserts the layer's segments (zero-length ones bound nothing and are skipped) into a CGAL
/// arrangement, gives every face the winding number its segments' directions make (each segment
/// has the material on its left; overlapping segments add up), and returns the boundaries between
/// faces the fill rule puts inside and faces it puts outside, walked with the inside on the left.
/// Where the segments do not close up, each unbalanced end point v is joined by a horizontal
/// edge from x_left to v, carrying the imbalance, x_left being the smallest of `left_of` and the
/// end points' x: the region is then exactly the one SPEC §2's +x crossing rule makes solid,
/// clipped at x_left (pass the grid's x0: the region is then cut at the grid's left edge).
/// Collinear consecutive vertices are dropped. Throws what CGAL throws.
/// @pre rule is NonZero or EvenOdd.
ArrangementContours arrangement_contours(const ExactLayer& layer, FillRule rule, double left_of);

}  // namespace strata::exact::detail
