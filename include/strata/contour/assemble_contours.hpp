#pragma once

#include "strata/contour/contour.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/layer_segments.hpp"

namespace strata {

/// Joins a layer's segments into loops by topology: a segment that ends on mesh edge E is
/// followed by a segment that starts on E. Where an edge has several candidates (non-manifold
/// input) they are paired in facet order; chains that do not close are returned as Open
/// contours with their end points, never closed by a guess. Every segment is used exactly once.
/// Loops are classified Outer / Hole by orientation and given their nesting depth.
/// Complexity: O(s log s) for s segments, plus the nesting test on closed loops.
LayerContours assemble_contours(const LayerSegments& segments);

/// The same loops, checked exactly on the crossing points of `mesh` (the mesh the segments were
/// cut from): sets `loops_cross` (two pieces of the loops cross or touch, consecutive pieces of a
/// loop at their shared end excepted) and, when no loops cross, `misnested` (orientation does not
/// alternate with nesting depth), and then takes each loop's kind and depth from exact
/// predicates (kind from the turn at its lexicographically smallest vertex). A layer whose loops
/// are not simple (LayerContours::loops_are_simple) needs the outline of its filled region.
/// Complexity: O(s log s) for the crossing test on a bucket grid (about one segment a bucket),
/// plus the nesting test; exact arithmetic only where the double filter cannot decide.
/// Robustness: every decision exact (SPEC §2b).
LayerContours assemble_contours(const IndexedMesh& mesh, const LayerSegments& segments);

}  // namespace strata
