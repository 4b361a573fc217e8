#pragma once

#include <cstddef>
#include <string>

namespace strata::test {

/// The bytes of base64 `text` as the page's atob() reads them: characters outside the alphabet
/// (padding, line breaks) are skipped.
std::string base64_decode(const std::string& text);

/// The `size` bytes a zlib stream (as DecompressionStream("deflate") reads it) inflates to;
/// fails the current test when the stream is not valid zlib or inflates to another size.
std::string inflate(const std::string& packed, std::size_t size);

}  // namespace strata::test
