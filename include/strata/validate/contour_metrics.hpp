#pragma once

#include <span>

#include "strata/contour/contour.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/validate/validation_report.hpp"

namespace strata::validate {

/// The symmetric difference of the regions two contour sets bound, and each region's area.
struct SymmetricDifference {
  double area_mm2 = 0.0;  ///< area of the points in exactly one of the two regions
  double area_a_mm2 = 0.0;
  double area_b_mm2 = 0.0;
  AreaMethod method = AreaMethod::Identical;
};

/// Compares the regions that two sets of contours bound in one plane (exact Boolean operation).
///
/// Each set's region is taken from its closed loops under the fill rule, through the winding
/// number of every point (+1 inside a counter-clockwise loop, -1 inside a clockwise one, summed
/// over the loops): NonZero keeps the points with winding != 0, EvenOdd the points with an odd
/// winding. Loops may touch, overlap, repeat or cross themselves; open chains are ignored.
/// When both sets have the same directed loop edges the result is 0 without further work
/// (AreaMethod::Identical). Otherwise all edges go into one CGAL arrangement of Epeck segments
/// carrying each set's winding change, the winding numbers of both sets are propagated face by
/// face from the unbounded face, and the areas of the faces are summed exactly (GMP rationals)
/// and rounded once. If CGAL raises an error, the result falls back to AreaMethod::AreaOnly
/// with |net area a - net area b|.
/// @param rule NonZero or EvenOdd (Winding is treated as NonZero)
/// Complexity: O((n + i) log n) for n edges and i crossings, in exact arithmetic.
SymmetricDifference symmetric_difference(std::span<const Contour> a, std::span<const Contour> b,
                                         FillRule rule);

/// True when the closed loops of both sets have the same directed edges (zero-length edges left
/// out), as multisets of exact double coordinates: then they bound the same region under any
/// fill rule. Open chains are ignored.
bool same_loop_edges(std::span<const Contour> a, std::span<const Contour> b);

/// Symmetric Hausdorff distance between two contour sets, in mm: the largest distance from a
/// vertex of one set to the nearest piece of the other, both ways. A contour's pieces are its
/// segments (the closing segment included when it is closed), or its single point when it has
/// one point. Distances are computed in double from the stored points (a measurement, not a
/// decision). Returns 0 when both sets are empty and +infinity when only one is.
/// Complexity: about O((n + m) log) with a uniform grid over the segments and early termination.
double hausdorff_distance(std::span<const Contour> a, std::span<const Contour> b);

}  // namespace strata::validate
