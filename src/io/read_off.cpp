// OFF reader, hand-written rather than CGAL::IO::read_OFF because CGAL 5.5's reader:
//  - sizes its arrays from unchecked counts: the header's vertex and face counts, and each face's
//    corner count ("4000000000 0 1 2" resizes one polygon to 32 GB; found by fuzzing), so a
//    hostile file exhausts memory instead of failing;
//  - rejects counts glued to the keyword ("OFF8 6 12", trimesh/models/whitespace.off in the
//    corpus);
//  - cannot say on which line a file is bad.
// Read: the optional keyword [ST][C][N][4][n]OFF, the counts (vertices, faces, edges), one vertex
// a line (x y z, x y z w for 4OFF, `dim` coordinates for nOFF; the rest of the line, normals,
// colours, texture coordinates, ignored) and the faces (n i1 ... in, then an optional colour).
// Binary OFF is reported as unsupported.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "io/read_mesh_internal.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io::detail {
namespace {

/// Tokens of the text with their line numbers; `#` starts a comment to the end of the line.
class OffTokens {
 public:
  OffTokens(std::string_view text, const ReadLimits& limits) : text_(text), limits_(limits) {}

  /// The next token, or empty at the end of the text (or on a line over the limit).
  std::string_view next() {
    for (;;) {
      while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;
      if (pos_ >= text_.size()) return {};
      const char c = text_[pos_];
      if (c == '\n' || c == '\r') {
        const bool crlf = c == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n';
        pos_ += crlf ? 2 : 1;
        new_line();
        continue;
      }
      if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
        continue;
      }
      break;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n' &&
           text_[pos_] != '\r' && text_[pos_] != '#') {
      ++pos_;
    }
    if (pos_ - line_start_ > limits_.max_line_bytes) {
      too_long_ = true;
      pos_ = text_.size();
      return {};
    }
    return text_.substr(start, pos_ - start);
  }

  /// Skips the rest of the current line (extra per-vertex or per-face values).
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') {
      if (pos_ - line_start_ > limits_.max_line_bytes) {
        too_long_ = true;
        pos_ = text_.size();
        return;
      }
      ++pos_;
    }
  }

  std::size_t line() const { return line_; }
  bool too_long() const { return too_long_; }
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  void new_line() {
    ++line_;
    line_start_ = pos_;
  }

  std::string_view text_;
  const ReadLimits& limits_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
  bool too_long_ = false;
};

std::string shown(std::string_view token) {
  std::string out;
  for (const char c : token.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f) ? '?' : c;
  }
  return out;
}

/// The OFF keyword's prefixes, e.g. "CNOFF" -> colour and normals.
struct OffKeyword {
  bool homogeneous = false;  ///< 4OFF: x y z w
  bool dimension = false;    ///< nOFF: the dimension comes before the counts
};

/// The flags of a keyword from what precedes its "OFF" (`prefix`); nullopt when they are none.
std::optional<OffKeyword> parse_keyword_prefix(std::string_view prefix) {
  OffKeyword keyword;
  if (!prefix.empty() && prefix.back() == 'n') {
    keyword.dimension = true;
    prefix.remove_suffix(1);
  }
  if (!prefix.empty() && prefix.back() == '4') {
    keyword.homogeneous = true;
    prefix.remove_suffix(1);
  }
  for (const std::string_view flag :
       {std::string_view("N"), std::string_view("C"), std::string_view("ST")}) {
    if (prefix.ends_with(flag)) prefix.remove_suffix(flag.size());
  }
  if (!prefix.empty()) return std::nullopt;
  return keyword;
}

}  // namespace

Result<TriangleSoup> read_off_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits) {
  OffTokens tokens(bytes, limits);
  auto error = [&](std::string message) {
    return Error{ErrorCode::BadInput, std::move(message),
                 fmt::format("{}:{}", name, tokens.line())};
  };
  auto number_error = [&](std::string_view token, const auto& scanned) {
    return bad_number(fmt::format("{}:{}", name, tokens.line()), token, scanned);
  };
  auto token_or_end = [&](std::string_view what) -> Result<std::string_view> {
    const std::string_view token = tokens.next();
    if (!token.empty()) return token;
    if (tokens.too_long()) {
      return error(fmt::format("line longer than the limit of {} bytes", limits.max_line_bytes));
    }
    return error(fmt::format("file ends where {} was expected (truncated?)", what));
  };

  // Keyword (optional), possibly with the counts glued to it ("OFF8 6 12").
  Result<std::string_view> first = token_or_end("the OFF keyword");
  if (!first) return first.error();
  std::string_view word = *first;
  OffKeyword keyword;
  Diagnostics diagnostics;
  std::string_view glued;
  {
    std::size_t split = word.find("OFF");
    if (split != std::string_view::npos) {
      const auto parsed = parse_keyword_prefix(word.substr(0, split));
      split += 3;
      if (!parsed) return error(fmt::format("unknown OFF keyword '{}'", shown(word)));
      keyword = *parsed;
      if (split < word.size()) {
        glued = word.substr(split);
        diagnostics.push_back(Diagnostic{
            Severity::Warning, "off.glued_counts",
            fmt::format("{}:{}: counts glued to the OFF keyword '{}'; read as if separated", name,
                        tokens.line(), shown(word))});
      }
      word = {};
    }
  }
  auto next_value = [&](std::string_view what) -> Result<std::string_view> {
    if (!glued.empty()) return std::exchange(glued, std::string_view{});
    if (!word.empty()) return std::exchange(word, std::string_view{});
    return token_or_end(what);
  };

  std::size_t coordinates = 3;
  if (keyword.dimension) {
    Result<std::string_view> dim = next_value("the dimension");
    if (!dim) return dim.error();
    if (*dim == "BINARY") {
      return Error{ErrorCode::BadInput, "unsupported format: binary OFF", std::string(name)};
    }
    const ScannedNumber<std::uint64_t> scanned = scan_unsigned(*dim, NumberType::UInt64);
    if (!scanned.ok()) return number_error(*dim, scanned);
    if (scanned.value < 3 || scanned.value > 16) {
      return error(fmt::format("nOFF dimension '{}' is not an integer from 3 to 16", shown(*dim)));
    }
    coordinates = static_cast<std::size_t>(scanned.value);
  }
  if (keyword.homogeneous) ++coordinates;

  std::uint64_t counts[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    Result<std::string_view> t = next_value(k == 0 ? "the vertex count" : "the face count");
    if (!t) return t.error();
    if (k == 0 && *t == "BINARY") {
      return Error{ErrorCode::BadInput, "unsupported format: binary OFF", std::string(name)};
    }
    const ScannedNumber<std::uint64_t> scanned = scan_unsigned(*t, NumberType::UInt64);
    if (!scanned.ok()) return number_error(*t, scanned);
    counts[k] = scanned.value;
  }
  tokens.skip_line();  // the edge count, when present, is not needed
  // A vertex takes at least 6 bytes ("0 0 0\n"), a face 2: larger counts are lies and must not
  // size an allocation.
  if (counts[0] > bytes.size() / 6 + 1 || counts[1] > bytes.size() / 2 + 1) {
    return error(
        fmt::format("header declares {} vertices and {} faces, more than a file of {} "
                    "bytes can hold (truncated?)",
                    counts[0], counts[1], bytes.size()));
  }
  if (counts[1] > limits.max_triangles) {
    return error(fmt::format("header declares {} faces, more than the limit of {}", counts[1],
                             limits.max_triangles));
  }

  PolygonSoup polygons;
  polygons.points.reserve(counts[0]);
  for (std::uint64_t v = 0; v < counts[0]; ++v) {
    double values[17] = {};
    for (std::size_t k = 0; k < coordinates; ++k) {
      Result<std::string_view> t = token_or_end(fmt::format("vertex {}", v));
      if (!t) return t.error();
      const ScannedNumber<double> scanned = scan_real(*t);  // double, not rounded: SPEC §2
      if (!scanned.ok()) return number_error(*t, scanned);
      values[k] = scanned.value;
    }
    tokens.skip_line();  // normals, colours, texture coordinates
    std::array<double, 3> p{values[0], values[1], values[2]};
    if (keyword.homogeneous) {
      const double w = values[coordinates - 1];
      if (w == 0.0) return error(fmt::format("vertex {} has the homogeneous weight 0", v));
      for (double& c : p) c /= w;
    }
    // Every number read is finite; only the division by a tiny weight can overflow.
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      return error(fmt::format(
          "vertex {} divided by its weight {} is too large for a double; NaN and infinity cannot "
          "be sliced",
          v, values[coordinates - 1]));
    }
    polygons.points.push_back(p);
  }

  polygons.face_offsets.reserve(counts[1] + 1);
  polygons.face_lines.reserve(counts[1]);
  for (std::uint64_t f = 0; f < counts[1]; ++f) {
    Result<std::string_view> t = token_or_end(fmt::format("face {}", f));
    if (!t) return t.error();
    const std::size_t line = tokens.line();
    const ScannedNumber<std::uint64_t> corner_count = scan_unsigned(*t, NumberType::UInt64);
    if (!corner_count.ok()) return number_error(*t, corner_count);
    const std::uint64_t n = corner_count.value;
    if (n > tokens.remaining() / 2 + 1) {
      return error(fmt::format(
          "face {} declares {} corners, more than the rest of the file holds (truncated?)", f, n));
    }
    for (std::uint64_t c = 0; c < n; ++c) {
      Result<std::string_view> index_token = token_or_end(fmt::format("a corner of face {}", f));
      if (!index_token) return index_token.error();
      const ScannedNumber<std::uint64_t> index = scan_unsigned(*index_token, NumberType::UInt64);
      if (!index.ok()) return number_error(*index_token, index);
      polygons.corners.push_back(static_cast<std::size_t>(index.value));
    }
    tokens.skip_line();  // the face colour
    polygons.face_offsets.push_back(polygons.corners.size());
    polygons.face_lines.push_back(line);
  }

  Result<TriangleSoup> soup = triangulate_polygons(polygons, name, "OFF", 0, limits);
  if (!soup) return soup;
  soup->diagnostics.insert(soup->diagnostics.begin(), diagnostics.begin(), diagnostics.end());
  soup->format = "off";
  return soup;
}

}  // namespace strata::io::detail
