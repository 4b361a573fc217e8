#include "strata/io/cells_format.hpp"

#include <algorithm>

namespace strata::io {

void append_packed_cells(std::span<const CellClass> cells, std::string& out) {
  const std::size_t n = cells.size();
  const std::size_t start = out.size();
  out.resize(start + (n + 3) / 4);
  char* to = out.data() + start;
  const auto code = [&](std::size_t idx) { return static_cast<unsigned>(cells[idx]); };
  const std::size_t whole = n / 4;
  for (std::size_t b = 0; b < whole; ++b) {
    const std::size_t c = 4 * b;
    to[b] = static_cast<char>(code(c) << 6 | code(c + 1) << 4 | code(c + 2) << 2 | code(c + 3));
  }
  if (whole * 4 < n) {
    unsigned byte = 0;
    for (std::size_t idx = whole * 4; idx < n; ++idx) {
      byte |= code(idx) << (6 - 2 * (idx - whole * 4));
    }
    to[whole] = static_cast<char>(byte);
  }
}

}  // namespace strata::io
