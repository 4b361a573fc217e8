// Binary STL: the bytes as a file `fuzz.stl`, then again with the header's facet count set to
// what the size holds, so that mutated facet records always reach the binary reader and the
// slicer instead of stopping at the size check.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = strata::fuzz::as_bytes(data, size);
  strata::fuzz::read_and_slice(bytes, "fuzz.stl");

  constexpr std::size_t kHeader = 84;
  constexpr std::size_t kFacet = 50;
  if (size < kHeader) return 0;
  std::string fitted(bytes);
  const std::uint32_t count = static_cast<std::uint32_t>((size - kHeader) / kFacet);
  for (int b = 0; b < 4; ++b) fitted[80 + b] = static_cast<char>((count >> (8 * b)) & 0xff);
  if (fitted != bytes) strata::fuzz::read_and_slice(fitted, "fuzz.stl");
  return 0;
}
