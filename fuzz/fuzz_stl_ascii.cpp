// ASCII STL (and gzip-compressed STL): the bytes as a file `fuzz.stl`. The reader tells binary
// from ASCII by content; the seeds of this target are ASCII and gzip files.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  strata::fuzz::read_and_slice(strata::fuzz::as_bytes(data, size), "fuzz.stl");
  return 0;
}
