#include "strata/io/read_mesh.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/huge_pages.hpp"
#include "io/ascii_case_internal.hpp"
#include "io/read_mesh_internal.hpp"
#include "io/stl_format_internal.hpp"

namespace strata::io {
namespace {

Error bad_input(std::string_view name, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::string(name)};
}

using detail::lower_ascii;

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

/// The lower-case extension of a name, with its dot (".stl"), or "" when it has none.
std::string extension_of(std::string_view name) {
  const std::size_t slash = name.find_last_of("/\\");
  const std::string_view file = slash == std::string_view::npos ? name : name.substr(slash + 1);
  const std::size_t dot = file.rfind('.');
  if (dot == std::string_view::npos || dot == 0) return {};
  return lower_ascii(file.substr(dot));
}

bool starts_with_ply_magic(std::string_view bytes) {
  return bytes.size() >= 4 && bytes.substr(0, 3) == "ply" && (bytes[3] == '\n' || bytes[3] == '\r');
}

/// First token of the text, skipping `#` comment lines: an OFF keyword is [ST][C][N][4][n]OFF.
bool looks_like_off(std::string_view bytes) {
  std::size_t i = 0;
  for (;;) {
    while (i < bytes.size() &&
           (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\n' || bytes[i] == '\r')) {
      ++i;
    }
    if (i < bytes.size() && bytes[i] == '#') {
      while (i < bytes.size() && bytes[i] != '\n' && bytes[i] != '\r') ++i;
      continue;
    }
    break;
  }
  std::size_t j = i;
  while (j < bytes.size() && j - i < 8 && bytes[j] > ' ') ++j;
  const std::string_view word = bytes.substr(i, j - i);
  return ends_with(word, "OFF") && (j == bytes.size() || bytes[j] <= ' ');
}

/// An OBJ file is text whose statements start with `v`, `f`, `#`, `o`, `g` ...: accept it when
/// one of its first lines is a `v ` statement.
bool looks_like_obj(std::string_view bytes) {
  std::size_t line_start = 0;
  for (int line = 0; line < 64 && line_start < bytes.size(); ++line) {
    const std::string_view rest = bytes.substr(line_start);
    if (rest.size() >= 2 && rest[0] == 'v' && (rest[1] == ' ' || rest[1] == '\t')) return true;
    const std::size_t eol = rest.find('\n');
    if (eol == std::string_view::npos) break;
    line_start += eol + 1;
  }
  return false;
}

Result<TriangleSoup> unsupported(std::string_view name, std::string_view what) {
  return bad_input(name, fmt::format("unsupported format: {}; strata reads STL (binary or ASCII), "
                                     "OBJ, OFF, PLY (optionally gzip-compressed) and 3MF",
                                     what));
}

bool starts_with_zip_magic(std::string_view bytes) {
  return bytes.substr(0, 4) == std::string_view("PK\x03\x04", 4);
}

bool has_unsupported_extension(std::string_view ext) {
  return ext == ".amf" || ext == ".zip" || ext == ".ctm" || ext == ".step" || ext == ".stp" ||
         ext == ".iges" || ext == ".igs" || ext == ".fbx" || ext == ".dae" || ext == ".gltf" ||
         ext == ".glb" || ext == ".3ds" || ext == ".x3d" || ext == ".wrl";
}

/// Whether uncompressed content beginning with `head` (its first 84 bytes at least, where it has
/// them), `size` bytes in all, is read as a binary STL: decided from the head alone, so that a
/// file can be read a block of records at a time. Not a 3MF or zip, a size that fits the
/// header's facet count, not an extension of a format we refuse, not PLY.
bool reads_as_binary_stl(std::string_view head, std::uint64_t size, std::string_view inner_name) {
  const std::string ext = extension_of(inner_name);
  if (ext == ".3mf" || starts_with_zip_magic(head)) return false;
  const detail::StlBinaryFit fit = detail::stl_binary_layout(head, size).fit;
  return (fit == detail::StlBinaryFit::Exact || fit == detail::StlBinaryFit::TrailingBytes) &&
         !has_unsupported_extension(ext) && !starts_with_ply_magic(head);
}

/// Dispatch on uncompressed bytes; `inner_name` is the name without `.gz`. A 3MF soup is in
/// millimetres already (the file states its unit); the other formats are scaled by the caller.
Result<TriangleSoup> read_uncompressed(std::string_view bytes, std::string_view name,
                                       std::string_view inner_name, const ReadLimits& limits,
                                       const CoordinateScale& scale) {
  if (bytes.empty()) return bad_input(name, "empty file (0 bytes)");
  if (reads_as_binary_stl(bytes, bytes.size(), inner_name)) {
    return read_stl_bytes(bytes, name, limits);
  }
  // A 3MF file is a zip archive: its name decides, or, without an extension, its zip magic.
  // Before the text decoding below, which would take a zip's bytes for text.
  const std::string ext = extension_of(inner_name);
  if (ext == ".3mf" || (ext.empty() && starts_with_zip_magic(bytes))) {
    return detail::read_3mf_bytes(bytes, name, limits, scale);
  }
  if (starts_with_zip_magic(bytes)) return unsupported(name, "zip archive");
  const detail::StlBinaryLayout layout = detail::stl_binary_layout(bytes);
  // A binary STL's 80-byte header is free text: bytes that fit its size are never decoded.
  if (layout.fit != detail::StlBinaryFit::Exact &&
      layout.fit != detail::StlBinaryFit::TrailingBytes) {
    Result<detail::TextBytes> text = detail::decode_text_encoding(bytes, name);
    if (!text) return text.error();
    if (!text->encoding.empty()) {
      Result<TriangleSoup> soup =
          read_uncompressed(text->text(bytes), name, inner_name, limits, scale);
      if (!soup) return soup;
      soup->diagnostics.insert(
          soup->diagnostics.begin(),
          Diagnostic{Severity::Info, "io.text_encoding",
                     fmt::format("{}: {} text, decoded before reading", name, text->encoding)});
      return soup;
    }
  }
  if (has_unsupported_extension(ext)) {
    return unsupported(name, fmt::format("'{}' files", ext));
  }
  if (starts_with_ply_magic(bytes)) return detail::read_ply_bytes(bytes, name, limits);

  if (layout.fit == detail::StlBinaryFit::Exact ||
      layout.fit == detail::StlBinaryFit::TrailingBytes || detail::starts_with_solid(bytes) ||
      ext == ".stl") {
    return read_stl_bytes(bytes, name, limits);
  }
  if (ext == ".obj") return detail::read_obj_bytes(bytes, name, limits);
  if (ext == ".off") return detail::read_off_bytes(bytes, name, limits);
  if (ext == ".ply") return detail::read_ply_bytes(bytes, name, limits);
  if (looks_like_off(bytes)) return detail::read_off_bytes(bytes, name, limits);
  if (looks_like_obj(bytes)) return detail::read_obj_bytes(bytes, name, limits);
  if (bytes.substr(0, 5) == "<?xml" || bytes.substr(0, 4) == "<amf") {
    return unsupported(name, "XML (AMF?)");
  }
  return unsupported(name, ext.empty()
                               ? std::string("content is not STL, OBJ, OFF or PLY")
                               : fmt::format("'{}' content is not STL, OBJ, OFF or PLY", ext));
}

/// Converts the coordinates read to millimetres (CoordinateScale).
Result<void> apply_scale(TriangleSoup& soup, std::string_view name, const CoordinateScale& scale) {
  const double factor = scale.factor();
  if (factor == 1.0) return {};
  // The 3MF reader converted from the file's own unit and applied the factor.
  if (soup.format.starts_with("3mf")) return {};
  // STL is single precision (SPEC §2): the scaled coordinate is a float32 again.
  const bool single = soup.format.starts_with("stl");
  const double largest =
      single ? std::numeric_limits<float>::max() : std::numeric_limits<double>::max();
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    for (Vec3& corner : soup.triangles[t]) {
      for (double* c : {&corner.x, &corner.y, &corner.z}) {
        const double scaled = *c * factor;
        if (!(std::fabs(scaled) <= largest)) {
          return Error{ErrorCode::BadInput,
                       fmt::format("coordinate {} in {} is {} mm, beyond the largest {} ({:g})", *c,
                                   length_unit_name(scale.units), scaled,
                                   single ? "STL coordinate (float32)" : "double", largest),
                       fmt::format("{}: facet {}", name, t)};
        }
        *c = single ? static_cast<double>(static_cast<float>(scaled)) : scaled;
      }
    }
  }
  return {};
}

Result<TriangleSoup> read_any(std::string_view bytes, std::string_view name,
                              const ReadLimits& limits, const CoordinateScale& scale) {
  if (!detail::is_gzip(bytes)) return read_uncompressed(bytes, name, name, limits, scale);

  const std::string lower = lower_ascii(name);
  std::string_view inner_name = name;
  if (ends_with(lower, ".gz")) inner_name.remove_suffix(3);
  if (ends_with(lower, ".tgz")) return unsupported(name, "tar archive");

  Result<std::string> inflated =
      detail::decompress_gzip(bytes, name, limits.max_decompressed_bytes);
  if (!inflated) return inflated.error();
  if (detail::is_gzip(*inflated)) {
    return unsupported(name, "gzip inside gzip");
  }
  Result<TriangleSoup> soup = read_uncompressed(*inflated, name, inner_name, limits, scale);
  if (!soup) {
    if (inflated->empty()) return bad_input(name, "empty file (gzip of 0 bytes)");
    return soup;
  }
  soup->format += "+gz";
  return soup;
}

/// The soup `read` returns, converted to millimetres; a scale factor that is not a finite
/// number > 0 is refused before anything is read.
template <class Read>
Result<TriangleSoup> read_scaled(std::string_view name, const CoordinateScale& scale, Read read) {
  if (!(scale.scale > 0.0) || !std::isfinite(scale.scale)) {
    return Error{ErrorCode::Usage,
                 fmt::format("the scale factor must be a finite number > 0, got {}", scale.scale),
                 {}};
  }
  Result<TriangleSoup> soup = read();
  if (!soup) return soup;
  if (auto scaled = apply_scale(*soup, name, scale); !scaled) return scaled.error();
  return soup;
}

/// A file descriptor closed when it goes out of scope.
class OpenFile {
 public:
  explicit OpenFile(const std::filesystem::path& path)
      : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  ~OpenFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  int fd() const { return fd_; }

  /// Why the last read_at failed: the system's error, or the file ending first.
  static Error read_error(std::string_view name) {
    return bad_input(name, fmt::format("cannot read: {}",
                                       errno != 0 ? std::strerror(errno) : "the file got shorter"));
  }

  /// Reads `length` bytes at `offset`; false on an error or when the file ends first.
  bool read_at(char* into, std::size_t length, std::uint64_t offset) const {
    while (length > 0) {
      const ssize_t got = ::pread(fd_, into, length, static_cast<off_t>(offset));
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) return false;
      if (got == 0) {
        errno = 0;  // the file ended first (read_error)
        return false;
      }
      into += got;
      length -= static_cast<std::size_t>(got);
      offset += static_cast<std::uint64_t>(got);
    }
    return true;
  }

 private:
  int fd_;
};

/// A binary STL file read a block of records at a time, each block straight into the converting
/// thread's scratch: the file is never held whole, and the copy out of the page cache is shared
/// among the threads.
Result<TriangleSoup> read_binary_stl_file(const OpenFile& file, std::string_view head,
                                          std::uint64_t size, std::string_view name,
                                          const ReadLimits& limits) {
  const auto blocks = [&file](std::uint32_t first, std::uint32_t count,
                              std::vector<char>& scratch) -> const char* {
    const std::size_t bytes = std::size_t{count} * detail::kStlBinaryFacetBytes;
    if (scratch.size() < bytes) scratch.resize(bytes);
    const std::uint64_t offset =
        detail::kStlBinaryHeaderBytes + std::uint64_t{first} * detail::kStlBinaryFacetBytes;
    return file.read_at(scratch.data(), bytes, offset) ? scratch.data() : nullptr;
  };
  return detail::read_stl_records(blocks, size, name, detail::stl_binary_layout(head, size),
                                  limits);
}

}  // namespace

Result<TriangleSoup> read_mesh_bytes(std::string_view bytes, std::string_view name,
                                     const ReadLimits& limits, const CoordinateScale& scale) {
  return read_scaled(name, scale, [&] { return read_any(bytes, name, limits, scale); });
}

Result<TriangleSoup> read_mesh(const std::filesystem::path& path, const ReadLimits& limits,
                               const CoordinateScale& scale) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    return bad_input(name, "cannot open: no such file");
  }
  if (std::filesystem::is_directory(status)) {
    return bad_input(name, "cannot read: it is a directory, not a file");
  }
  const OpenFile file(path);
  if (file.fd() < 0) return bad_input(name, fmt::format("cannot open: {}", std::strerror(errno)));
  struct stat info {};
  if (::fstat(file.fd(), &info) != 0) {
    return bad_input(name, fmt::format("cannot read: {}", std::strerror(errno)));
  }
  std::unique_ptr<char[]> buffer;
  std::string streamed;
  std::string_view bytes;
  // A regular file's size, or, for a device, where seeking to its end goes: 0 for /dev/zero
  // (read as an empty file rather than without end), none for a pipe or a terminal.
  const off_t end = S_ISREG(info.st_mode) ? info.st_size : ::lseek(file.fd(), 0, SEEK_END);
  if (end > 0) {
    const auto size = static_cast<std::uint64_t>(end);
    std::array<char, detail::kStlBinaryHeaderBytes> head_bytes{};
    const std::size_t head_size = std::min<std::uint64_t>(size, head_bytes.size());
    if (!file.read_at(head_bytes.data(), head_size, 0)) return file.read_error(name);
    const std::string_view head(head_bytes.data(), head_size);
    if (!detail::is_gzip(head) && reads_as_binary_stl(head, size, name)) {
      return read_scaled(name, scale,
                         [&] { return read_binary_stl_file(file, head, size, name, limits); });
    }
    // Any other file is read whole into storage that is not zeroed first, advised to huge pages
    // when it is large.
    const auto length = static_cast<std::size_t>(size);
    buffer = std::make_unique_for_overwrite<char[]>(length);
    advise_huge_pages(buffer.get(), length);
    if (!file.read_at(buffer.get(), length, 0)) return file.read_error(name);
    bytes = std::string_view(buffer.get(), length);
  } else if (end < 0) {
    // Not seekable (a pipe, a terminal): read it as a stream.
    std::array<char, 65536> chunk{};
    for (;;) {
      const ssize_t got = ::read(file.fd(), chunk.data(), chunk.size());
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) return bad_input(name, fmt::format("cannot read: {}", std::strerror(errno)));
      if (got == 0) break;
      streamed.append(chunk.data(), static_cast<std::size_t>(got));
    }
    bytes = streamed;
  }
  if (bytes.empty()) return bad_input(name, "empty file (0 bytes)");
  return read_mesh_bytes(bytes, name, limits, scale);
}

}  // namespace strata::io
