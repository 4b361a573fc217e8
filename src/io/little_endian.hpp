#pragma once

// Little-endian encoding of integers and IEEE numbers, shared by the cells reader and the
// writers of src/export/.

#include <cstdint>
#include <cstring>
#include <string>

namespace strata::io::detail {

inline void put_u16_le(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xffu));
  out.push_back(static_cast<char>((v >> 8) & 0xffu));
}

inline void put_u32_le(std::string& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>((v >> shift) & 0xffu));
}

inline void put_i32_le(std::string& out, std::int32_t v) {
  put_u32_le(out, static_cast<std::uint32_t>(v));
}

inline void put_f32_le(std::string& out, float v) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  put_u32_le(out, bits);
}

inline void put_f64_le(std::string& out, double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (int shift = 0; shift < 64; shift += 8)
    out.push_back(static_cast<char>((bits >> shift) & 0xffu));
}

inline std::uint32_t get_u32_le(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
         (std::uint32_t{p[3]} << 24);
}

inline double get_f64_le(const unsigned char* p) {
  std::uint64_t bits = 0;
  for (int b = 0; b < 8; ++b) bits |= std::uint64_t{p[b]} << (8 * b);
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace strata::io::detail
