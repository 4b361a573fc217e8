// Adds an empty entry to a zip archive held in memory: the local entry goes after the last one,
// the central directory is copied after it with one more record, and the end record is
// rewritten (PKWARE's APPNOTE 4.3). Only plain archives (no ZIP64, one disk) are handled.
#include <cstdint>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

constexpr std::uint32_t kEndSignature = 0x06054b50;
constexpr std::uint32_t kCentralSignature = 0x02014b50;
constexpr std::size_t kEndSize = 22;
constexpr std::size_t kCentralSize = 46;

std::uint32_t read16(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8;
}

std::uint32_t read32(std::string_view b, std::size_t at) {
  return read16(b, at) | read16(b, at + 2) << 16;
}

void put16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xFF);
  out += static_cast<char>((v >> 8) & 0xFF);
}

void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xFFFF);
  put16(out, v >> 16);
}

}  // namespace

std::optional<std::string> append_empty_zip_entry(std::string_view zip, std::string_view name) {
  if (zip.size() < kEndSize || name.size() > 0xFFFF) return std::nullopt;
  // The end record is the last 22 bytes plus a comment of at most 65535 bytes.
  std::size_t end = zip.size() - kEndSize;
  const std::size_t lowest = zip.size() > kEndSize + 0xFFFF ? zip.size() - kEndSize - 0xFFFF : 0;
  while (read32(zip, end) != kEndSignature) {
    if (end == lowest) return std::nullopt;
    --end;
  }
  const std::uint32_t disk = read16(zip, end + 4);
  const std::uint32_t directory_disk = read16(zip, end + 6);
  const std::uint32_t entries = read16(zip, end + 10);
  const std::uint32_t directory_size = read32(zip, end + 12);
  const std::uint32_t directory_offset = read32(zip, end + 16);
  if (disk != 0 || directory_disk != 0 || entries == 0xFFFF || read16(zip, end + 8) != entries ||
      directory_offset == 0xFFFFFFFF || std::size_t{directory_offset} + directory_size > end) {
    return std::nullopt;
  }
  // An archive that holds the entry already is left as it is.
  const std::string_view directory = zip.substr(directory_offset, directory_size);
  std::size_t at = 0;
  for (std::uint32_t i = 0; i < entries; ++i) {
    if (at + kCentralSize > directory.size() || read32(directory, at) != kCentralSignature) {
      return std::nullopt;
    }
    const std::size_t name_size = read16(directory, at + 28);
    const std::size_t record =
        kCentralSize + name_size + read16(directory, at + 30) + read16(directory, at + 32);
    if (at + record > directory.size()) return std::nullopt;
    if (directory.substr(at + kCentralSize, name_size) == name) return std::nullopt;
    at += record;
  }

  std::string local;  // APPNOTE 4.3.7: version 2.0, stored, no date, CRC and sizes 0
  put32(local, 0x04034b50);
  put16(local, 20);
  put16(local, 0);
  put16(local, 0);
  put16(local, 0);
  put16(local, 0x21);
  put32(local, 0);
  put32(local, 0);
  put32(local, 0);
  put16(local, static_cast<std::uint32_t>(name.size()));
  put16(local, 0);
  local += name;
  std::string central;  // APPNOTE 4.3.12
  put32(central, kCentralSignature);
  put16(central, 20);
  put16(central, 20);
  put16(central, 0);
  put16(central, 0);
  put16(central, 0);
  put16(central, 0x21);
  put32(central, 0);
  put32(central, 0);
  put32(central, 0);
  put16(central, static_cast<std::uint32_t>(name.size()));
  put16(central, 0);
  put16(central, 0);
  put16(central, 0);
  put16(central, 0);
  put32(central, 0);
  put32(central, directory_offset);
  central += name;
  const std::uint64_t new_offset = std::uint64_t{directory_offset} + local.size();
  const std::uint64_t new_size = std::uint64_t{directory_size} + central.size();
  if (new_offset + new_size > 0xFFFFFFFFu) return std::nullopt;

  std::string out;
  out.reserve(zip.size() + local.size() + central.size());
  out.append(zip.substr(0, directory_offset));
  out += local;
  // The new record goes right after the entries' own: bytes the directory holds past them (its
  // size larger than its records) stay after it, where they cannot be read as its start.
  out.append(directory.substr(0, at));
  out += central;
  out.append(directory.substr(at));
  put32(out, kEndSignature);
  put16(out, 0);
  put16(out, 0);
  put16(out, entries + 1);
  put16(out, entries + 1);
  put32(out, static_cast<std::uint32_t>(new_size));
  put32(out, static_cast<std::uint32_t>(new_offset));
  put16(out, 0);
  return out;
}

}  // namespace strata::io::detail
