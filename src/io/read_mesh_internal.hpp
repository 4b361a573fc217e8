#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "strata/core/diagnostic.hpp"
#include "strata/core/result.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io::detail {

/// Spaces and tabs that separate tokens on a line of a text mesh format.
constexpr bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

/// Splits off the next blank-separated token of `rest` (empty at the end of the line).
inline std::string_view next_token(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && is_blank(rest[i])) ++i;
  std::size_t j = i;
  while (j < rest.size() && !is_blank(rest[j])) ++j;
  const std::string_view token = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return token;
}

/// Collects repeated warnings of one kind into a single Diagnostic: the first occurrence's
/// message, a count and the first few further places, so that a file with 10^6 odd normals
/// yields one line, not 10^6.
class DiagnosticTally {
 public:
  /// @param place_kind  what the `where` numbers are, e.g. "line" or "facet"
  explicit DiagnosticTally(std::string place_kind) : place_kind_(std::move(place_kind)) {}

  /// Records one occurrence at `where`; `make_message` is called only for the first one of
  /// `code` and must name the place itself.
  template <class MakeMessage>
  void add(std::string_view code, Severity severity, std::size_t where,
           MakeMessage&& make_message) {
    if (count_again(code, where)) return;
    entries_.push_back(Entry{std::string(code), severity, make_message(), 1, {}});
  }

  /// Appends one Diagnostic per code, in order of first occurrence.
  void flush_into(Diagnostics& out) const;

 private:
  /// Counts one more occurrence at `where` when `code` was seen before; false for a new code.
  /// Kept out of the template so the search is one function, not one for each message maker.
  bool count_again(std::string_view code, std::size_t where);

  static constexpr std::size_t kMaxPlaces = 8;
  struct Entry {
    std::string code;
    Severity severity;
    std::string message;
    std::size_t count;
    std::vector<std::size_t> more;
  };
  std::string place_kind_;
  std::vector<Entry> entries_;
};

/// Inflates gzip data (one or more members) held in memory.
/// @param name       used in error messages
/// @param max_bytes  the decompressed size that makes reading fail (against compression bombs)
Result<std::string> decompress_gzip(std::string_view bytes, std::string_view name,
                                    std::size_t max_bytes);

/// True when the bytes start with the gzip magic 1f 8b.
bool is_gzip(std::string_view bytes);

/// How a text mesh file is encoded, as decode_text_encoding found it.
struct TextBytes {
  std::size_t mark_bytes = 0;  ///< length of the byte-order mark (0 when there is none)
  std::string_view
      encoding;  ///< "UTF-8 with a byte-order mark", "UTF-16 LE", "UTF-16 BE"; "" for none
  std::optional<std::string> decoded;  ///< the text as UTF-8, for UTF-16

  /// The text the readers take: `decoded` when set, else `bytes` without the mark.
  std::string_view text(std::string_view bytes) const {
    return decoded ? std::string_view(*decoded) : bytes.substr(mark_bytes);
  }
};

/// The one decoding step before the text readers: a UTF-8 byte-order mark is dropped, UTF-16 LE
/// or BE with a mark is decoded to UTF-8 (line numbers stay those of the file).
/// @return Error{BadInput} naming the file for UTF-32 (with or without a mark), for text that
///         looks like UTF-16 without a mark (ASCII bytes with NUL bytes between them), and for
///         invalid UTF-16 (odd length, unpaired surrogate, with its byte offset)
Result<TextBytes> decode_text_encoding(std::string_view bytes, std::string_view name);

/// Wavefront OBJ: `v` and `f` lines (other statements ignored), polygons fan-triangulated.
Result<TriangleSoup> read_obj_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits);

/// ASCII OFF (and its COFF/NOFF/4OFF/nOFF variants), polygons fan-triangulated; binary OFF is
/// reported as unsupported.
Result<TriangleSoup> read_off_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits);

/// PLY, ASCII or binary little/big endian; `face` lists fan-triangulated.
Result<TriangleSoup> read_ply_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits);

/// `zip` with one more entry, `name`, of no bytes (stored); nullopt when `zip` is not a plain
/// zip archive (no end record, ZIP64, several disks, a damaged central directory) or already
/// holds an entry of that name.
std::optional<std::string> append_empty_zip_entry(std::string_view zip, std::string_view name);

/// 3MF through lib3mf: every mesh of the build, placed and in millimetres (assemble_3mf_mesh,
/// which also says how `scale` applies); soup.format "3mf". Errors name the file and what lib3mf
/// or the assembly found wrong.
Result<TriangleSoup> read_3mf_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits, const CoordinateScale& scale);

/// Polygons as the OBJ/OFF/PLY readers produce them, before triangulation.
struct PolygonSoup {
  std::vector<std::array<double, 3>> points;
  /// Corner indices (0-based into points) of all faces, one face after the other.
  std::vector<std::size_t> corners;
  /// Face f has corners [face_offsets[f], face_offsets[f + 1]); starts with a single 0.
  std::vector<std::size_t> face_offsets{0};
  /// The line of each face when the reader knows it (empty otherwise).
  std::vector<std::size_t> face_lines;

  std::size_t num_faces() const { return face_offsets.size() - 1; }
};

/// Converts polygons into triangle fans (corner 0 with each following pair), checking every index
/// and every used coordinate. Faces with fewer than three corners are skipped with a warning.
/// @param what        the format, used in messages ("OBJ", "OFF", "PLY")
/// @param index_base  how the format numbers vertices in messages (OBJ 1, OFF and PLY 0)
/// @return the soup (format left empty), or Error{BadInput} naming the face and, when known, line
Result<TriangleSoup> triangulate_polygons(const PolygonSoup& polygons, std::string_view name,
                                          std::string_view what, std::size_t index_base,
                                          const ReadLimits& limits);

}  // namespace strata::io::detail
