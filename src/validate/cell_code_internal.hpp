#pragma once

#include "strata/voxel/cell_class.hpp"

namespace strata::validate::detail {

/// A cell class as the reports write it, its two bits of the cells file: "00", "01" or "11"
/// ("10", the reserved code, for any other value).
inline const char* cell_code(CellClass c) {
  // Indexed by the code itself: no case is left that no class can reach.
  static constexpr const char* kCodes[] = {"00", "01", "10", "11"};
  return kCodes[static_cast<unsigned>(c) & 3U];
}

}  // namespace strata::validate::detail
