#pragma once

#include "strata/contour/contour.hpp"
#include "strata/slice/layer_segments.hpp"

namespace strata {

/// Joins a layer's segments into loops by topology: a segment that ends on mesh edge E is
/// followed by a segment that starts on E. Where an edge has several candidates (non-manifold
/// input) they are paired in facet order; chains that do not close are returned as Open
/// contours with their end points, never closed by a guess. Every segment is used exactly once.
/// Loops are classified Outer / Hole by orientation and given their nesting depth.
/// Complexity: O(s log s) for s segments, plus the nesting test on closed loops.
LayerContours assemble_contours(const LayerSegments& segments);

}  // namespace strata
