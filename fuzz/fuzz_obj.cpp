// The bytes as a file `fuzz.obj`: the format dispatch, the OBJ reader, the fan triangulation,
// then weld and slice.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  strata::fuzz::read_and_slice(strata::fuzz::as_bytes(data, size), "fuzz.obj");
  return 0;
}
