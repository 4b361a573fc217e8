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
};

}  // namespace strata
