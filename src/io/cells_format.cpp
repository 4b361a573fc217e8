#include "strata/io/cells_format.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace strata::io {

namespace {

// Cells are one byte each: four of them read as a little-endian word w hold cell c in bits
// 8c..8c+7. Multiplied by 2^30 + 2^20 + 2^10 + 1, cell c's code (two bits) lands at bit
// 24 + 6 - 2c, the packed byte's place for it, at bits 24..31; the other products fall at
// least two bits below bit 24 (their sum stays under 2^24) or above bit 31.
constexpr std::uint64_t kPackMultiplier = (1ULL << 30) | (1ULL << 20) | (1ULL << 10) | 1ULL;
constexpr bool kLittleEndian = std::endian::native == std::endian::little;

std::uint32_t load_word(const CellClass* cells) {
  std::uint32_t w = 0;
  std::memcpy(&w, cells, sizeof w);
  return w;
}

std::uint64_t load_double_word(const CellClass* cells) {
  std::uint64_t w = 0;
  std::memcpy(&w, cells, sizeof w);
  return w;
}

}  // namespace

void append_packed_cells(std::span<const CellClass> cells, std::string& out) {
  static_assert(sizeof(CellClass) == 1, "a cell is one byte");
  const std::size_t n = cells.size();
  const std::size_t start = out.size();
  out.resize(start + (n + 3) / 4);
  char* to = out.data() + start;
  // Two bits a code: a wider value is the caller's to refuse (first_unstorable_cell).
  const auto code = [&](std::size_t idx) { return static_cast<unsigned>(cells[idx]) & 0b11U; };
  const std::size_t whole = n / 4;
  for (std::size_t b = 0; b < whole; ++b) {
    const std::size_t c = 4 * b;
    if constexpr (kLittleEndian) {
      const std::uint64_t w = load_word(cells.data() + c) & 0x03030303U;
      to[b] = static_cast<char>((w * kPackMultiplier) >> 24);
    } else {
      to[b] = static_cast<char>(code(c) << 6 | code(c + 1) << 4 | code(c + 2) << 2 | code(c + 3));
    }
  }
  if (whole * 4 < n) {
    unsigned byte = 0;
    for (std::size_t idx = whole * 4; idx < n; ++idx) {
      byte |= code(idx) << (6 - 2 * (idx - whole * 4));
    }
    to[whole] = static_cast<char>(byte);
  }
}

std::size_t first_unstorable_cell(std::span<const CellClass> cells) {
  const auto storable = [](CellClass c) {
    const auto code = static_cast<unsigned>(c);
    return code <= 0b11 && code != 0b10;
  };
  std::size_t idx = 0;
  if constexpr (kLittleEndian) {
    // Eight cells at a time: a byte above 3 has a bit in 0xFC; a byte of 2 has bit 1 without
    // bit 0.
    constexpr std::uint64_t kHigh = 0xFCFCFCFCFCFCFCFCULL;
    constexpr std::uint64_t kLow = 0x0101010101010101ULL;
    const auto unstorable_bits = [&](std::size_t at) {
      const std::uint64_t w = load_double_word(cells.data() + at);
      return (w & kHigh) | ((w >> 1) & ~w & kLow);
    };
    // Blocks of 256 cells without a branch inside, which the compiler takes several words a
    // step; the block that holds a bad code is searched word by word below.
    constexpr std::size_t kBlock = 256;
    for (; idx + kBlock <= cells.size(); idx += kBlock) {
      std::uint64_t bad = 0;
      for (std::size_t at = idx; at < idx + kBlock; at += 8) bad |= unstorable_bits(at);
      if (bad != 0) break;
    }
    for (; idx + 8 <= cells.size(); idx += 8) {
      if (unstorable_bits(idx) != 0) break;
    }
  }
  for (; idx < cells.size(); ++idx) {
    if (!storable(cells[idx])) return idx;
  }
  return cells.size();
}

}  // namespace strata::io
