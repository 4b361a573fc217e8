// gzip in memory with zlib; a file may hold several gzip members (as `cat a.gz b.gz` makes).
#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

Error gzip_error(std::string_view name, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::string(name)};
}

}  // namespace

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

Result<std::string> decompress_gzip(std::string_view bytes, std::string_view name,
                                    std::size_t max_bytes) {
  z_stream stream{};
  // 16 + MAX_WBITS: gzip wrapper only (the magic bytes have been checked by the caller).
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
    return gzip_error(name, "cannot initialise zlib");
  }
  std::string out;
  out.resize(std::min<std::size_t>(std::max<std::size_t>(bytes.size() * 4, 1 << 16), max_bytes));
  std::size_t produced = 0;
  std::size_t consumed = 0;
  int status = Z_OK;

  for (;;) {
    const std::size_t in_chunk = std::min<std::size_t>(bytes.size() - consumed, UINT_MAX);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + consumed));
    stream.avail_in = static_cast<uInt>(in_chunk);
    if (produced == out.size()) {
      if (out.size() >= max_bytes) {
        inflateEnd(&stream);
        return gzip_error(
            name, fmt::format("decompresses to more than the limit of {} bytes", max_bytes));
      }
      out.resize(std::min(out.size() * 2, max_bytes));
    }
    const std::size_t out_chunk = std::min<std::size_t>(out.size() - produced, UINT_MAX);
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
    stream.avail_out = static_cast<uInt>(out_chunk);

    status = inflate(&stream, Z_NO_FLUSH);
    consumed += in_chunk - stream.avail_in;
    produced += out_chunk - stream.avail_out;

    if (status == Z_STREAM_END) {
      // Another member follows only if it starts with the magic bytes; anything else is
      // trailing garbage, which gzip itself ignores with a warning.
      if (is_gzip(bytes.substr(consumed))) {
        inflateReset(&stream);
        continue;
      }
      break;
    }
    if (status == Z_NEED_DICT || status == Z_DATA_ERROR || status == Z_MEM_ERROR) {
      const std::string reason = stream.msg != nullptr ? stream.msg : "invalid data";
      inflateEnd(&stream);
      return gzip_error(
          name, fmt::format("corrupt gzip data after {} compressed bytes: {}", consumed, reason));
    }
    if (status == Z_BUF_ERROR && consumed == bytes.size() && produced < out.size()) {
      inflateEnd(&stream);
      return gzip_error(name, fmt::format("gzip data ends early (truncated file?) after {} "
                                          "decompressed bytes",
                                          produced));
    }
  }
  inflateEnd(&stream);
  out.resize(produced);
  return out;
}

}  // namespace strata::io::detail
