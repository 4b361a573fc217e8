#pragma once

// SHA-256 (FIPS 180-4), for fingerprints that tell models and option sets apart; not a security
// boundary.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace strata::detail {

class Sha256 {
 public:
  Sha256();
  /// Appends bytes to the message.
  void update(std::string_view bytes);
  /// The digest of the bytes so far, as 64 lower-case hex digits.
  std::string hex_digest() const;

  /// Whether whole blocks go to the processor's SHA instructions (x86-64 with the SHA
  /// extensions) rather than the plain C++ rounds.
  static bool uses_processor_extensions();
  /// Whether the processor's SHA rounds can be used, from CPUID leaf 1's ECX (SSSE3, bit 9;
  /// SSE4.1, bit 19) and leaf 7's EBX (SHA, bit 29): all three are needed.
  static bool extensions_usable(std::uint32_t leaf1_ecx, std::uint32_t leaf7_ebx);
  /// The digest of `bytes` by the plain C++ rounds alone, whatever the processor: for tests.
  static std::string portable_hex_digest(std::string_view bytes);

  /// Compresses `blocks` whole 64-byte blocks into the state.
  using CompressFunction = void (*)(std::uint32_t* state, const unsigned char* data,
                                    std::size_t blocks);

 private:
  std::array<std::uint32_t, 8> state_;
  std::array<unsigned char, 64> block_{};
  std::size_t block_used_ = 0;
  std::uint64_t length_bytes_ = 0;
  CompressFunction compress_;
};

}  // namespace strata::detail
