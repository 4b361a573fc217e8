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

/// The packed byte of the four cells in the low 32 bits of w (their codes' two low bits).
char pack_four(std::uint64_t w) {
  return static_cast<char>(((w & 0x03030303U) * kPackMultiplier) >> 24);
}

/// Nonzero when one of the eight cells of w holds a code the encoding cannot store: a byte above
/// 3 has a bit in 0xFC; a byte of 2 has bit 1 without bit 0.
std::uint64_t unstorable_bits(std::uint64_t w) {
  constexpr std::uint64_t kHigh = 0xFCFCFCFCFCFCFCFCULL;
  constexpr std::uint64_t kLow = 0x0101010101010101ULL;
  return (w & kHigh) | ((w >> 1) & ~w & kLow);
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
      to[b] = pack_four(load_word(cells.data() + c));
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

std::size_t append_checked_packed_cells(std::span<const CellClass> cells, std::string& out) {
  if constexpr (!kLittleEndian) {
    const std::size_t bad = first_unstorable_cell(cells);
    if (bad == cells.size()) append_packed_cells(cells, out);
    return bad;
  }
  const std::size_t n = cells.size();
  const std::size_t start = out.size();
  out.resize(start + (n + 3) / 4);
  char* to = out.data() + start;
  // Eight cells a word, checked as first_unstorable_cell checks them and packed as
  // append_packed_cells packs them (two bytes, four cells each): the layer is read once.
  std::uint64_t unstorable = 0;
  const std::size_t words = n / 8;
  for (std::size_t b = 0; b < words; ++b) {
    const std::uint64_t w = load_double_word(cells.data() + 8 * b);
    unstorable |= unstorable_bits(w);
    to[2 * b] = pack_four(w);
    to[2 * b + 1] = pack_four(w >> 32);
  }
  const std::span<const CellClass> rest = cells.subspan(8 * words);
  if (unstorable != 0 || first_unstorable_cell(rest) < rest.size()) {
    out.resize(start);
    return first_unstorable_cell(cells);
  }
  // The last cells, fewer than eight, as append_packed_cells packs them.
  out.resize(start + 2 * words);
  append_packed_cells(rest, out);
  return n;
}

std::size_t first_unstorable_cell(std::span<const CellClass> cells) {
  const auto storable = [](CellClass c) {
    const auto code = static_cast<unsigned>(c);
    return code <= 0b11 && code != 0b10;
  };
  std::size_t idx = 0;
  if constexpr (kLittleEndian) {
    // Eight cells at a time.
    const auto unstorable_at = [&](std::size_t at) {
      return unstorable_bits(load_double_word(cells.data() + at));
    };
    // Blocks of 256 cells without a branch inside, which the compiler takes several words a
    // step; the block that holds a bad code is searched word by word below.
    constexpr std::size_t kBlock = 256;
    for (; idx + kBlock <= cells.size(); idx += kBlock) {
      std::uint64_t bad = 0;
      for (std::size_t at = idx; at < idx + kBlock; at += 8) bad |= unstorable_at(at);
      if (bad != 0) break;
    }
    for (; idx + 8 <= cells.size(); idx += 8) {
      if (unstorable_at(idx) != 0) break;
    }
  }
  for (; idx < cells.size(); ++idx) {
    if (!storable(cells[idx])) return idx;
  }
  return cells.size();
}

}  // namespace strata::io
