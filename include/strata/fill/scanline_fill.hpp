#pragma once

#include <cstdint>
#include <vector>

#include "strata/fill/solid_rows.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/layer_segments.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// A piece of scanline inside the solid: row j, from x_start to x_end (mm, rounded).
struct HatchSegment {
  std::uint32_t row = 0;
  double x_start = 0.0;
  double x_end = 0.0;
};

/// What scanline_fill computes.
struct FillWanted {
  bool cells = true;    ///< LayerFill::solid (empty when false)
  bool hatches = true;  ///< LayerFill::hatches
};

/// The solid cells of one layer and its hatches.
struct LayerFill {
  std::uint32_t layer = 0;
  /// The cells whose centre is inside, as runs along the rows; no rows when the cells were not
  /// wanted.
  SolidRows solid;
  std::vector<HatchSegment> hatches;
  /// Crossings counted in this layer (for the report).
  std::uint64_t crossings = 0;
  /// Decisions that the double filter could not take and exact arithmetic took.
  std::uint64_t exact_fallbacks = 0;
};

/// The exact inside rule of SPEC §2 for `nonzero` and `evenodd`: row j's scanline
/// y = yc(j) + scan_offset crosses a segment when exactly one end point has y below it; the
/// crossing counts for cell i when its exact x is greater than xc(i), adding sign(nx) of the
/// facet normal. Every comparison is a sign of a polynomial in the input coordinates, taken by
/// a double filter with an exact (GMP) fallback, never with a tolerance.
/// Hatches alone need no cell decided: their crossings' x is all they are made of.
/// @pre rule is NonZero or EvenOdd; segments come from slice_layer on the same mesh and grid.
LayerFill scanline_fill(const IndexedMesh& mesh, const LayerSegments& segments,
                        const GridSpec& grid, FillRule rule, double scan_offset_mm,
                        FillWanted wanted);

/// The integer winding number of every cell centre of the layer (nx * ny, row-major): the sum of
/// sign(nx) over the crossings right of the centre, by the same exact rule as scanline_fill.
/// For a closed (or cycle-closed) surface this is its winding number around the centre; the
/// `winding` fill rule builds on it.
std::vector<std::int32_t> scanline_winding_numbers(const IndexedMesh& mesh,
                                                   const LayerSegments& segments,
                                                   const GridSpec& grid, double scan_offset_mm);

}  // namespace strata
