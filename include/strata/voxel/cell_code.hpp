#pragma once

#include "strata/voxel/cell_class.hpp"

namespace strata {

/// The two digits by which the text outputs name a cell's class, as the ASCII cells file writes
/// them: "00", "01" or "11"; "10" for the reserved code.
inline const char* cell_code(CellClass c) {
  switch (c) {
    case CellClass::Empty:
      return "00";
    case CellClass::Interior:
      return "01";
    case CellClass::Boundary:
      return "11";
  }
  return "10";
}

}  // namespace strata
