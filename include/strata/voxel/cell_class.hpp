#pragma once

#include <cstdint>

namespace strata {

/// The codes of the cells file (SPEC §3.1); 0b10 is reserved.
enum class CellClass : std::uint8_t {
  Empty = 0b00,
  Interior = 0b01,
  Boundary = 0b11,
};

}  // namespace strata
