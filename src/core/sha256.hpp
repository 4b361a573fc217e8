#pragma once

// SHA-256 (FIPS 180-4), for fingerprints that tell models and option sets apart; not a security
// boundary.

#include <array>
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

 private:
  void compress(const unsigned char* block);

  std::array<std::uint32_t, 8> state_;
  std::array<unsigned char, 64> block_{};
  std::size_t block_used_ = 0;
  std::uint64_t length_bytes_ = 0;
};

}  // namespace strata::detail
