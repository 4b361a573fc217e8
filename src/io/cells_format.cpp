#include "strata/io/cells_format.hpp"

#include <algorithm>

namespace strata::io {

void append_packed_cells(std::span<const CellClass> cells, std::string& out) {
  const std::size_t n = cells.size();
  out.reserve(out.size() + (n + 3) / 4);
  for (std::size_t base = 0; base < n; base += 4) {
    unsigned byte = 0;
    const std::size_t end = std::min(base + 4, n);
    for (std::size_t idx = base; idx < end; ++idx) {
      byte |= static_cast<unsigned>(cells[idx]) << (6 - 2 * (idx - base));
    }
    out.push_back(static_cast<char>(byte));
  }
}

}  // namespace strata::io
