#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "export/grey_png_internal.hpp"

namespace strata::io::detail {

namespace {

constexpr std::uint32_t kAdlerModulus = 65521;
constexpr std::uint32_t kMaxMatch = 258;
constexpr std::uint32_t kWindow = 32768;

/// Deflate's length symbols 257 .. 285: the first length of each and its extra bits.
constexpr std::array<std::uint16_t, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                                       15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                                       67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
/// Distance codes 0 .. 29: the first distance of each and its extra bits.
constexpr std::array<std::uint16_t, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<std::uint8_t, 30> kDistanceExtra = {0, 0, 0,  0,  1,  1,  2,  2,  3,  3,
                                                         4, 4, 5,  5,  6,  6,  7,  7,  8,  8,
                                                         9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/// The index of the last base not above `value` (value at least bases[0]).
template <std::size_t N>
constexpr std::size_t code_of(const std::array<std::uint16_t, N>& bases, std::uint32_t value) {
  std::size_t i = 0;
  while (i + 1 < N && bases[i + 1] <= value) ++i;
  return i;
}

/// `code` in `length` bits, most significant first, as the low bits of a least-significant-first
/// stream take it (deflate's Huffman codes).
constexpr std::uint32_t reversed(std::uint32_t code, int length) {
  std::uint32_t out = 0;
  for (int i = 0; i < length; ++i) out |= ((code >> i) & 1U) << (length - 1 - i);
  return out;
}

/// The fixed code of a literal byte (RFC 1951 §3.2.6).
constexpr DeflateCode literal_code(std::uint32_t byte) {
  return byte < 144 ? DeflateCode{reversed(0x30U + byte, 8), 8}
                    : DeflateCode{reversed(0x190U + byte - 144, 9), 9};
}

/// A match length 3 .. 258: its symbol's fixed code and the extra bits.
constexpr DeflateCode length_code(std::uint32_t length) {
  const std::size_t l = code_of(kLengthBase, length);
  const std::uint32_t symbol = 257 + static_cast<std::uint32_t>(l);
  const DeflateCode code = symbol < 280 ? DeflateCode{reversed(symbol - 256, 7), 7}
                                        : DeflateCode{reversed(0xC0U + symbol - 280, 8), 8};
  return {code.bits | (length - kLengthBase[l]) << code.count, code.count + kLengthExtra[l]};
}

/// A distance 1 .. 32768: its code (five bits) and the extra bits.
constexpr DeflateCode distance_code(std::uint32_t distance) {
  const std::size_t d = code_of(kDistanceBase, distance);
  return {reversed(static_cast<std::uint32_t>(d), 5) | (distance - kDistanceBase[d]) << 5,
          5 + kDistanceExtra[d]};
}

template <class Make, std::size_t N>
constexpr std::array<DeflateCode, N> table(Make make, std::uint32_t first) {
  std::array<DeflateCode, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = make(first + static_cast<std::uint32_t>(i));
  return out;
}
constexpr auto kLiteralCodes = table<decltype(&literal_code), 256>(&literal_code, 0);
constexpr auto kLengthCodes = table<decltype(&length_code), 256>(&length_code, 3);  // 3 .. 258
constexpr DeflateCode kDistanceOne = distance_code(1);

/// n (n + 1) / 2 modulo the Adler modulus, without overflow.
std::uint64_t triangle_mod(std::uint64_t n) {
  return n % 2 == 0 ? (n / 2 % kAdlerModulus) * ((n + 1) % kAdlerModulus)
                    : (n % kAdlerModulus) * ((n + 1) / 2 % kAdlerModulus);
}

/// Adds `count` copies of `byte` to the Adler-32 sums a, b: a gains count * byte, and b gains
/// count * a plus byte * (1 + 2 + ... + count).
void add_run(std::uint32_t& a, std::uint32_t& b, std::uint8_t byte, std::uint64_t count) {
  const std::uint64_t n = count % kAdlerModulus;
  const std::uint64_t new_b = b + n * a + byte * (triangle_mod(count) % kAdlerModulus);
  a = static_cast<std::uint32_t>((a + n * byte) % kAdlerModulus);
  b = static_cast<std::uint32_t>(new_b % kAdlerModulus);
}

void put_u32(std::string& out, std::uint32_t v) {
  const char bytes[4] = {static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                         static_cast<char>(v >> 8), static_cast<char>(v)};
  out.append(bytes, 4);
}

/// A PNG chunk: its length, type, data and the CRC of type and data.
void put_chunk(std::string& out, const char* type, std::string_view data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  out.append(type, 4);
  out.append(data);
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
  // zlib's length type may be 32 bits: the data goes in pieces.
  for (std::size_t at = 0; at < data.size(); at += std::size_t{1} << 30) {
    const std::size_t piece = std::min(data.size() - at, std::size_t{1} << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data.data() + at), static_cast<uInt>(piece));
  }
  put_u32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

RowDeflater::RowDeflater(std::size_t row_bytes, std::string& out)
    : row_bytes_(row_bytes),
      out_(out),
      bits_(out),
      previous_(row_bytes),
      // Rows longer than the window are never copied: their distance is not used.
      row_distance_(distance_code(
          static_cast<std::uint32_t>(std::clamp<std::size_t>(row_bytes, 1, kWindow)))) {
  // zlib header: deflate with a 32 KiB window, no dictionary, a check that makes it a multiple
  // of 31; then one final block of fixed Huffman codes.
  out_.push_back(static_cast<char>(0x78));
  out_.push_back(static_cast<char>(0x01));
  bits_.put(1, 1);
  bits_.put(1, 2);
}

void RowDeflater::literal(std::uint8_t byte) { bits_.put(kLiteralCodes[byte]); }

void RowDeflater::copies(std::uint64_t length, DeflateCode distance) {
  while (length > 0) {
    std::uint64_t take = std::min<std::uint64_t>(length, kMaxMatch);
    // A match is 3 bytes at least: leave the last piece three.
    if (length > kMaxMatch && length - take < 3) take = length - 3;
    bits_.put(kLengthCodes[take - 3]);
    bits_.put(distance);
    length -= take;
  }
}

void RowDeflater::flush_run() {
  if (run_ >= 3) {
    copies(run_, kDistanceOne);
  } else {
    for (std::uint64_t i = 0; i < run_; ++i) literal(last_);
  }
  run_ = 0;
}

void RowDeflater::add_to_checksum_run(std::uint8_t byte, std::uint64_t count) {
  add_run(adler_a_, adler_b_, byte, count);
  add_run(row_a_, row_b_, byte, count);
}

void RowDeflater::add_row(const std::uint8_t* row) {
  const std::size_t n = row_bytes_;
  if (has_previous_ && n >= 3 && n <= kWindow && std::memcmp(row, previous_.data(), n) == 0) {
    // The row above again: copies of it, and its sums added to the checksum's.
    flush_run();
    copies(n, row_distance_);
    const std::uint64_t length = n % kAdlerModulus;
    adler_b_ = static_cast<std::uint32_t>((adler_b_ + length * adler_a_ + row_b_) % kAdlerModulus);
    adler_a_ = (adler_a_ + row_a_) % kAdlerModulus;
    last_ = row[n - 1];
    has_last_ = true;
    return;
  }
  row_a_ = 0;
  row_b_ = 0;
  for (std::size_t i = 0; i < n;) {
    const std::uint8_t byte = row[i];
    std::size_t j = i + 1;
    // Eight bytes a compare through the long runs.
    const std::uint64_t eight = 0x0101010101010101ULL * byte;
    for (std::uint64_t word = 0; j + 8 <= n; j += 8) {
      std::memcpy(&word, row + j, 8);
      if (word != eight) break;
    }
    while (j < n && row[j] == byte) ++j;
    const std::uint64_t count = j - i;
    add_to_checksum_run(byte, count);
    if (has_last_ && byte == last_) {
      run_ += count;
    } else {
      flush_run();
      literal(byte);
      last_ = byte;
      has_last_ = true;
      run_ = count - 1;
    }
    i = j;
  }
  std::memcpy(previous_.data(), row, n);
  has_previous_ = true;
}

void RowDeflater::finish() {
  flush_run();
  bits_.put(0, 7);  // end of block (256): seven zero bits
  bits_.flush();
  put_u32(out_, adler_b_ << 16 | adler_a_);
}

GreyPngEncoder::GreyPngEncoder(std::uint32_t width, std::uint32_t height,
                               std::uint32_t pixels_per_metre_x, std::uint32_t pixels_per_metre_y)
    : width_(width),
      height_(height),
      ppm_x_(pixels_per_metre_x),
      ppm_y_(pixels_per_metre_y),
      row_(std::size_t{width} + 1, 0),
      deflater_(std::size_t{width} + 1, idat_) {}

void GreyPngEncoder::add_row() { deflater_.add_row(row_.data()); }

std::string GreyPngEncoder::finish() {
  deflater_.finish();
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put_u32(header, width_);
  put_u32(header, height_);
  header.append("\x08\x00\x00\x00\x00", 5);  // 8 bits, grey, deflate, adaptive filters, none
  put_chunk(png, "IHDR", header);
  if (ppm_x_ != 0 && ppm_y_ != 0) {
    std::string phys;
    put_u32(phys, ppm_x_);
    put_u32(phys, ppm_y_);
    phys.push_back('\x01');  // the unit is the metre
    put_chunk(png, "pHYs", phys);
  }
  // A chunk holds 2^31 - 1 bytes at most: a larger stream is split across several.
  constexpr std::size_t kMaxChunk = std::size_t{1} << 30;
  for (std::size_t at = 0; at < idat_.size(); at += kMaxChunk) {
    put_chunk(png, "IDAT", std::string_view(idat_).substr(at, kMaxChunk));
  }
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace strata::io::detail
