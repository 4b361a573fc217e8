#pragma once

#include "strata/voxel/cell_class.hpp"

namespace strata {

/// The two digits by which the text outputs name a cell's class, as the ASCII cells file writes
/// them: "00", "01" or "11"; "10" for the reserved code.
inline const char* cell_code(CellClass c) {
  // Indexed by the code itself: no case is left that no class can reach.
  static constexpr const char* kCodes[] = {"00", "01", "10", "11"};
  return kCodes[static_cast<unsigned>(c) & 3U];
}

}  // namespace strata
