#pragma once

#include <cstdint>
#include <vector>

#include "strata/mesh/vec3.hpp"

namespace strata {

/// What a loop is, by its orientation seen from +z (SPEC §3.2, the CLI `dir` codes).
enum class LoopKind : std::uint8_t {
  Hole = 0,   ///< closed, clockwise
  Outer = 1,  ///< closed, counter-clockwise
  Open = 2,   ///< a chain whose ends did not meet: reported, never closed silently
};

/// A chain of segments joined through shared mesh edges. A closed loop does not repeat its first
/// point at the end; `is_closed` says whether the last point joins the first.
struct Contour {
  std::vector<Point2> points;
  bool is_closed = false;
  LoopKind kind = LoopKind::Open;
  double signed_area_mm2 = 0.0;  ///< shoelace area, positive when counter-clockwise; 0 if open
  int depth = 0;                 ///< number of closed loops that contain this one
};

/// The contours of one layer.
struct LayerContours {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<Contour> loops;
  std::uint32_t open_chains = 0;
  /// Net area of the closed loops (sum of signed areas).
  double area_mm2 = 0.0;
  /// Two pieces of the chained loops cross or touch (issue 3): pieces of two chains, or two
  /// pieces of one chain that do not follow each other. Decided exactly.
  bool loops_cross = false;
  /// The chained loops neither cross nor touch, but their orientations do not alternate with
  /// nesting depth (outer loops counter-clockwise at even depth, holes clockwise at odd depth).
  bool misnested = false;
  /// The closed loops are the outline of the region the fill rule fills, from the exact
  /// arrangement, not the chained loops (see assemble_contours); Open loops are still the chains.
  bool outline = false;

  /// Every chain closed, no crossing or touching, orientations alternating with depth: then each
  /// chained loop bounds the region the fill rule fills, under nonzero and evenodd alike.
  bool loops_are_simple() const { return open_chains == 0 && !loops_cross && !misnested; }
};

}  // namespace strata
