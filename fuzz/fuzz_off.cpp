// The bytes as a file `fuzz.off`: the format dispatch, the OFF reader, the fan triangulation,
// then weld and slice.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  strata::fuzz::read_and_slice(strata::fuzz::as_bytes(data, size), "fuzz.off");
  return 0;
}
