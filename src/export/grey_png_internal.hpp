#pragma once

// An 8-bit grey PNG written row by row, compressed for what a layer is: long runs of a few grey
// levels, and rows often the same as the one above. Every run is a literal and copies of the
// byte before it, every row equal to the one above is copies of that row (deflate's
// back-references, in one block of fixed Huffman codes), and the zlib checksum of a run or a
// repeated row comes from a formula, not from its bytes. General compressors look at every byte
// of such an image several times; this looks at each once, and a repeated row only through
// memcmp.

#include <cstdint>
#include <string>
#include <vector>

namespace strata::io::detail {

/// Bits ready to append: a Huffman code (already reversed, as deflate stores it) and the extra
/// bits after it, `count` in all.
struct DeflateCode {
  std::uint32_t bits = 0;
  int count = 0;
};

/// Appends deflate codes to a string, least significant bit first (RFC 1951 §3.1.1).
class BitWriter {
 public:
  explicit BitWriter(std::string& out) : out_(out) {}
  /// The `count` (at most 32) low bits of `bits`, first bit first.
  void put(std::uint32_t bits, int count) {
    pending_ |= std::uint64_t{bits} << filled_;
    filled_ += count;
    while (filled_ >= 8) {
      out_.push_back(static_cast<char>(pending_ & 0xFFu));
      pending_ >>= 8;
      filled_ -= 8;
    }
  }
  void put(DeflateCode code) { put(code.bits, code.count); }
  /// Pads the last byte with zero bits.
  void flush() {
    if (filled_ > 0) out_.push_back(static_cast<char>(pending_ & 0xFFu));
    pending_ = 0;
    filled_ = 0;
  }

 private:
  std::string& out_;
  std::uint64_t pending_ = 0;
  int filled_ = 0;
};

/// A zlib stream (RFC 1950) of rows of equal length, given one at a time; finish() ends it.
class RowDeflater {
 public:
  RowDeflater(std::size_t row_bytes, std::string& out);
  void add_row(const std::uint8_t* row);
  void finish();

 private:
  void literal(std::uint8_t byte);
  /// Copies of the bytes `distance` back (length >= 3), as matches of at most 258.
  void copies(std::uint64_t length, DeflateCode distance);
  /// The run of the last byte that is not written yet.
  void flush_run();
  void add_to_checksum_run(std::uint8_t byte, std::uint64_t count);

  std::size_t row_bytes_;
  std::string& out_;
  BitWriter bits_;
  std::vector<std::uint8_t> previous_;
  bool has_previous_ = false;
  bool has_last_ = false;  ///< a byte was written: a run may copy it
  std::uint8_t last_ = 0;  ///< the last byte written
  std::uint64_t run_ = 0;  ///< copies of last_ not written yet
  std::uint32_t adler_a_ = 1, adler_b_ = 0;
  std::uint32_t row_a_ = 0, row_b_ = 0;  ///< the checksum sums of the last row alone
  DeflateCode row_distance_;             ///< the distance of the row above, row_bytes_
};

/// The bytes of an 8-bit grey PNG of `width` x `height` pixels (both at least 1), rows given top
/// first; pixels_per_metre_x and _y (both non-zero) add a pHYs chunk.
class GreyPngEncoder {
 public:
  GreyPngEncoder(std::uint32_t width, std::uint32_t height, std::uint32_t pixels_per_metre_x,
                 std::uint32_t pixels_per_metre_y);
  /// Where the next row's `width` grey levels go; add_row() then takes them.
  std::uint8_t* next_row() { return row_.data() + 1; }
  void add_row();
  /// The whole file, once every row was added.
  std::string finish();

 private:
  std::uint32_t width_, height_;
  std::uint32_t ppm_x_, ppm_y_;
  /// The filter byte, 0 (none: on three grey levels in long runs the others only add work), and
  /// a row.
  std::vector<std::uint8_t> row_;
  std::string idat_;
  RowDeflater deflater_;
};

}  // namespace strata::io::detail
