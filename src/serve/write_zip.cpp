#include "strata/serve/write_zip.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "strata/io/output_file.hpp"

namespace strata::serve {

namespace {

namespace fs = std::filesystem;

constexpr std::uint16_t kVersionNeeded = 20;  // deflate
constexpr std::uint16_t kUtf8Names = 0x0800;  // general purpose flag bit 11
constexpr std::uint16_t kStored = 0;
constexpr std::uint16_t kDeflated = 8;
constexpr std::uint16_t kDosTime = 0;
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01
constexpr std::uint64_t kLimit = std::numeric_limits<std::uint32_t>::max();

void put16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>(v >> 8));
}

void put32(std::string& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((v >> shift) & 0xff));
}

Result<std::string> read_file(const fs::path& path) {
  std::FILE* f = std::fopen(path.string().c_str(), "rb");
  if (f == nullptr) return Error{ErrorCode::BadInput, "cannot read the file", path.string()};
  std::string bytes;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) {
    bytes.append(buffer, n);
    if (bytes.size() > kLimit) break;
  }
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return Error{ErrorCode::BadInput, "cannot read the file", path.string()};
  if (bytes.size() > kLimit) {
    return Error{ErrorCode::BadInput, "larger than 4 GiB: too large for a ZIP entry",
                 path.string()};
  }
  return bytes;
}

/// Raw deflate (RFC 1951), as ZIP's method 8 stores it; empty when zlib fails.
std::string deflate_raw(const std::string& in) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    return {};
  }
  std::string out(deflateBound(&z, static_cast<uLong>(in.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return status == Z_STREAM_END ? out : std::string();
}

}  // namespace

Result<void> write_zip(const fs::path& archive, const std::vector<ZipEntry>& entries) {
  if (entries.size() > 0xffff) {
    return Error{ErrorCode::BadInput, "more than 65535 files for one ZIP archive",
                 archive.string()};
  }
  auto out = io::OutputFile::create(archive);
  if (!out) return out.error();
  std::string central;
  std::uint64_t offset = 0;
  for (const ZipEntry& entry : entries) {
    if (entry.name.empty() || entry.name.size() > 0xffff) {
      return Error{ErrorCode::BadInput, "a ZIP entry needs a name of 1 to 65535 bytes",
                   entry.source.string()};
    }
    auto data = read_file(entry.source);
    if (!data) return data.error();
    const auto crc = static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0),
                                                      reinterpret_cast<const Bytef*>(data->data()),
                                                      static_cast<uInt>(data->size())));
    std::string packed = deflate_raw(*data);
    const bool deflated = !packed.empty() && packed.size() < data->size();
    const std::string& stored = deflated ? packed : *data;
    const auto method = deflated ? kDeflated : kStored;

    std::string local;
    put32(local, 0x04034b50);
    put16(local, kVersionNeeded);
    put16(local, kUtf8Names);
    put16(local, method);
    put16(local, kDosTime);
    put16(local, kDosDate);
    put32(local, crc);
    put32(local, static_cast<std::uint32_t>(stored.size()));
    put32(local, static_cast<std::uint32_t>(data->size()));
    put16(local, static_cast<std::uint16_t>(entry.name.size()));
    put16(local, 0);
    local += entry.name;

    put32(central, 0x02014b50);
    put16(central, kVersionNeeded);
    put16(central, kVersionNeeded);
    put16(central, kUtf8Names);
    put16(central, method);
    put16(central, kDosTime);
    put16(central, kDosDate);
    put32(central, crc);
    put32(central, static_cast<std::uint32_t>(stored.size()));
    put32(central, static_cast<std::uint32_t>(data->size()));
    put16(central, static_cast<std::uint16_t>(entry.name.size()));
    put16(central, 0);  // extra
    put16(central, 0);  // comment
    put16(central, 0);  // disk
    put16(central, 0);  // internal attributes
    put32(central, 0);  // external attributes
    put32(central, static_cast<std::uint32_t>(offset));
    central += entry.name;

    out->write(local);
    out->write(stored);
    offset += local.size() + stored.size();
    if (offset > kLimit) {
      return Error{ErrorCode::BadInput, "the archive would pass 4 GiB (no ZIP64)",
                   archive.string()};
    }
  }
  std::string end;
  put32(end, 0x06054b50);
  put16(end, 0);
  put16(end, 0);
  put16(end, static_cast<std::uint16_t>(entries.size()));
  put16(end, static_cast<std::uint16_t>(entries.size()));
  put32(end, static_cast<std::uint32_t>(central.size()));
  put32(end, static_cast<std::uint32_t>(offset));
  put16(end, 0);
  if (offset + central.size() > kLimit) {
    return Error{ErrorCode::BadInput, "the archive would pass 4 GiB (no ZIP64)", archive.string()};
  }
  out->write(central);
  out->write(end);
  return out->commit();
}

Result<std::vector<ZipEntry>> zip_entries_of_folder(const fs::path& folder,
                                                    const std::string& prefix) {
  std::vector<ZipEntry> entries;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    entries.push_back(
        ZipEntry{prefix + it->path().lexically_relative(folder).generic_string(), it->path()});
  }
  if (ec) return Error{ErrorCode::BadInput, ec.message(), folder.string()};
  std::sort(entries.begin(), entries.end(),
            [](const ZipEntry& a, const ZipEntry& b) { return a.name < b.name; });
  return entries;
}

}  // namespace strata::serve
