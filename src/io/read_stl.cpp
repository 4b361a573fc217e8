// STL reading: binary and ASCII, told apart by content (SPEC §2, STYLE §4).
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/huge_pages.hpp"
#include "io/ascii_case_internal.hpp"
#include "io/little_endian.hpp"
#include "io/read_mesh_internal.hpp"
#include "io/stl_format_internal.hpp"
#include "io/text_format_internal.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io {
namespace {

using detail::is_blank;
using detail::next_token;

using detail::DiagnosticTally;
using detail::iequals_ascii;
using detail::kStlBinaryFacetBytes;
using detail::kStlBinaryHeaderBytes;
using detail::StlBinaryFit;
using detail::StlBinaryLayout;

Error bad_input(std::string location, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::move(location)};
}

std::string line_location(std::string_view name, std::size_t line) {
  return fmt::format("{}:{}", name, line);
}

std::string facet_location(std::string_view name, std::size_t facet) {
  return fmt::format("{}: facet {}", name, facet);
}

std::string quote(std::string_view text) { return detail::quote_input(text, 60); }

// ---------------------------------------------------------------------------------------------
// Binary

float load_float32_le(const char* p) {
  return std::bit_cast<float>(detail::get_u32_le(reinterpret_cast<const unsigned char*>(p)));
}

/// Records converted by one task, and read again together for the stored normals' messages.
constexpr std::uint32_t kRecordsABlock = 16384;

/// Touches every page of the storage a vector has reserved and not yet filled, the pages shared
/// among the threads. The kernel zeroes a page as it is first touched (a huge page: 2 MiB at a
/// time), which the vector's own initialisation would otherwise do on one thread.
void fault_in_parallel(void* storage, std::size_t bytes) {
  constexpr std::size_t kPage = 4096;
  constexpr std::size_t kPagesATask = 512;  // a huge page
  auto* first = static_cast<volatile char*>(storage);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bytes / kPage, kPagesATask),
                    [&](const auto& pages) {
                      for (std::size_t p = pages.begin(); p < pages.end(); ++p) {
                        first[p * kPage] = 0;
                      }
                    });
}

}  // namespace

namespace detail {

Result<TriangleSoup> read_stl_records(const StlRecordBlocks& blocks, std::uint64_t size,
                                      std::string_view name, const StlBinaryLayout& layout,
                                      const ReadLimits& limits) {
  const std::uint32_t count = layout.declared_facets;
  if (count == 0) {
    return bad_input(std::string(name), "no facets: the binary STL header declares 0 facets");
  }
  // Checked before any allocation: a hostile header must not make us reserve gigabytes.
  if (count > limits.max_triangles) {
    return bad_input(std::string(name),
                     fmt::format("header declares {} facets, more than the limit of {}", count,
                                 limits.max_triangles));
  }

  TriangleSoup soup;
  soup.format = "stl-binary";
  DiagnosticTally tally("facet");
  const auto load = [](const char* record) {
    std::array<float, 12> v{};
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = load_float32_le(record + 4 * k);
    return v;
  };
  const auto unreadable = [&](std::uint32_t first, std::uint32_t end) {
    return bad_input(
        facet_location(name, first),
        fmt::format("cannot read facets {} to {}: the file changed or failed while it was read",
                    first, end - 1));
  };
  const auto finite = [](const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  };

  // The records are independent: they are converted in parallel, and what is wrong with them is
  // reported afterwards in facet order, as a reading from the first record on would.
  reserve_huge_pages(soup.triangles, count);
  reserve_huge_pages(soup.stored_normals, count);
  fault_in_parallel(soup.triangles.data(), soup.triangles.capacity() * sizeof(soup.triangles[0]));
  fault_in_parallel(soup.stored_normals.data(),
                    soup.stored_normals.capacity() * sizeof(soup.stored_normals[0]));
  soup.triangles.resize(count);
  soup.stored_normals.resize(count);
  std::atomic<std::uint32_t> first_bad_corner{count};
  std::atomic<bool> any_bad_normal{false};
  std::atomic<std::uint32_t> first_unread{count};
  tbb::enumerable_thread_specific<std::vector<char>> scratches;
  tbb::parallel_for(
      tbb::blocked_range<std::uint32_t>(0, count, kRecordsABlock), [&](const auto& range) {
        const char* records = blocks(range.begin(), range.end() - range.begin(), scratches.local());
        if (records == nullptr) {
          for (std::uint32_t seen = first_unread.load();
               range.begin() < seen && !first_unread.compare_exchange_weak(seen, range.begin());) {
          }
          return;
        }
        std::uint32_t bad_corner = count;
        bool bad_normal = false;
        for (std::uint32_t f = range.begin(); f < range.end(); ++f) {
          const std::array<float, 12> v =
              load(records + std::size_t{f - range.begin()} * kStlBinaryFacetBytes);
          std::array<Vec3, 3>& triangle = soup.triangles[f];
          for (int c = 0; c < 3; ++c) {
            const float* p = v.data() + 3 + 3 * c;
            if (!finite(p)) bad_corner = std::min(bad_corner, f);
            // float -> double is exact (SPEC §2).
            triangle[c] = Vec3{p[0], p[1], p[2]};
          }
          if (finite(v.data())) {
            soup.stored_normals[f] = Vec3{v[0], v[1], v[2]};
          } else {
            bad_normal = true;  // the normal is ignored: it stays zero
          }
        }
        for (std::uint32_t seen = first_bad_corner.load();
             bad_corner < seen && !first_bad_corner.compare_exchange_weak(seen, bad_corner);) {
        }
        if (bad_normal) any_bad_normal = true;
      });

  if (const std::uint32_t f = first_unread.load(); f < count) {
    return unreadable(f, static_cast<std::uint32_t>(
                             std::min<std::uint64_t>(count, std::uint64_t{f} + kRecordsABlock)));
  }
  std::vector<char> scratch;
  if (const std::uint32_t f = first_bad_corner.load(); f < count) {
    const char* record = blocks(f, 1, scratch);
    if (record == nullptr) return unreadable(f, f + 1);
    const std::array<float, 12> v = load(record);
    for (int c = 0; c < 3; ++c) {
      const float* p = v.data() + 3 + 3 * c;
      if (finite(p)) continue;
      return bad_input(facet_location(name, f),
                       fmt::format("corner {} has a non-finite coordinate ({}, {}, {}); NaN and "
                                   "infinity cannot be sliced",
                                   c, p[0], p[1], p[2]));
    }
  }
  // Read again a block at a time, only when some normal is not finite: rare.
  for (std::uint64_t block = 0; any_bad_normal && block < count; block += kRecordsABlock) {
    const auto first = static_cast<std::uint32_t>(block);
    const std::uint32_t n = std::min(kRecordsABlock, count - first);
    const char* records = blocks(first, n, scratch);
    if (records == nullptr) return unreadable(first, first + n);
    for (std::uint32_t f = first; f < first + n; ++f) {
      const std::array<float, 12> v = load(records + std::size_t{f - first} * kStlBinaryFacetBytes);
      if (finite(v.data())) continue;
      tally.add("stl.bad_normal", Severity::Warning, f, [&] {
        return fmt::format(
            "{}: stored normal ({}, {}, {}) is not finite; the normal is ignored, "
            "the facet kept",
            facet_location(name, f), v[0], v[1], v[2]);
      });
    }
  }

  if (layout.fit == StlBinaryFit::TrailingBytes) {
    soup.diagnostics.push_back(Diagnostic{
        Severity::Warning, "stl.trailing_bytes",
        fmt::format("{}: {} stray byte{} after the last of the {} declared facets ignored ({} of "
                    "{} bytes used)",
                    name, layout.trailing_bytes, layout.trailing_bytes == 1 ? "" : "s", count,
                    layout.expected_bytes, size)});
  }
  tally.flush_into(soup.diagnostics);
  return soup;
}

}  // namespace detail

namespace {

Error binary_size_error(std::string_view bytes, std::string_view name,
                        const StlBinaryLayout& layout, std::string_view ascii_note) {
  const std::uint64_t size = bytes.size();
  std::string message;
  if (size < layout.expected_bytes) {
    const std::uint64_t whole = (size - kStlBinaryHeaderBytes) / kStlBinaryFacetBytes;
    message = fmt::format("header declares {} facets, file ends after {} ({} of {} bytes)",
                          layout.declared_facets, whole, size, layout.expected_bytes);
  } else {
    const std::uint64_t whole = (size - kStlBinaryHeaderBytes) / kStlBinaryFacetBytes;
    message = fmt::format(
        "header declares {} facets, but the file is {} bytes long, room for {} facets ({} bytes "
        "expected)",
        layout.declared_facets, size, whole, layout.expected_bytes);
  }
  if (!ascii_note.empty()) message += fmt::format("; {}", ascii_note);
  return bad_input(std::string(name), std::move(message));
}

// ---------------------------------------------------------------------------------------------
// ASCII

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

enum class Keyword { Solid, EndSolid, Facet, Outer, Vertex, EndLoop, EndFacet, Other };

Keyword classify(std::string_view token) {
  // Dispatch on length first: this runs once per line of multi-megabyte files.
  switch (token.size()) {
    case 5:
      if (iequals_ascii(token, "solid")) return Keyword::Solid;
      if (iequals_ascii(token, "facet")) return Keyword::Facet;
      if (iequals_ascii(token, "outer")) return Keyword::Outer;
      break;
    case 6:
      if (iequals_ascii(token, "vertex")) return Keyword::Vertex;
      break;
    case 7:
      if (iequals_ascii(token, "endloop")) return Keyword::EndLoop;
      break;
    case 8:
      if (iequals_ascii(token, "endsolid")) return Keyword::EndSolid;
      if (iequals_ascii(token, "endfacet")) return Keyword::EndFacet;
      break;
    default:
      break;
  }
  return Keyword::Other;
}

class AsciiStlParser {
 public:
  AsciiStlParser(std::string_view text, std::string_view name, const ReadLimits& limits)
      : text_(text), name_(name), limits_(limits), lines_(text, limits.max_line_bytes) {}

  Result<TriangleSoup> parse();

  /// True once a `facet` or `endsolid` line has been seen: the file is ASCII STL for sure, so
  /// its own error (with a line) is the one to report.
  bool recognised() const { return recognised_; }

 private:
  enum class State { Top, InSolid, InFacet };

  Error error_here(std::string message) const {
    return bad_input(line_location(name_, lines_.number()), std::move(message));
  }
  void begin_facet(std::string_view rest);
  Result<void> add_vertex(std::string_view rest);
  Result<void> finish_facet();
  void note_trailing(std::string_view keyword, std::string_view rest);

  std::string_view text_;
  std::string_view name_;
  const ReadLimits& limits_;
  detail::TextLines lines_;
  bool recognised_ = false;

  TriangleSoup soup_;
  DiagnosticTally tally_{"line"};
  std::vector<Vec3> facet_vertices_;
  Vec3 facet_normal_;
  std::size_t facet_line_ = 0;
  std::size_t skipped_facets_ = 0;
};

void AsciiStlParser::begin_facet(std::string_view rest) {
  facet_vertices_.clear();
  facet_line_ = lines_.number();
  facet_normal_ = Vec3{};
  const std::string_view after_facet = trim(rest);
  const std::string_view word = next_token(rest);
  const bool has_keyword = iequals_ascii(word, "normal");
  const std::string_view values = has_keyword ? trim(rest) : after_facet;
  std::array<double, 3> n{};
  bool ok = has_keyword;
  for (int k = 0; ok && k < 3; ++k) {
    // SPEC §2: STL is single precision, so ASCII numbers are rounded to float32 as they are read.
    const ScannedNumber<double> scanned = scan_real(next_token(rest), NumberType::Float32);
    ok = scanned.ok();
    n[k] = scanned.value;
  }
  if (!ok) {
    tally_.add("stl.bad_normal", Severity::Warning, lines_.number(), [&] {
      // Without values there is no word either: `values` is all of the line after `facet`
      // when it does not start with `normal`.
      return values.empty()
                 ? fmt::format("{}: facet has no stored normal values; the facet is kept",
                               line_location(name_, lines_.number()))
                 : fmt::format(
                       "{}: stored normal {} is not three finite numbers; the normal is "
                       "ignored, the facet kept",
                       line_location(name_, lines_.number()), quote(values));
    });
    return;
  }
  facet_normal_ = Vec3{n[0], n[1], n[2]};
  note_trailing("facet normal", rest);
}

Result<void> AsciiStlParser::add_vertex(std::string_view rest) {
  std::array<double, 3> p{};
  const auto here = [&] { return line_location(name_, lines_.number()); };
  if (auto r = detail::scan_vertex(rest, NumberType::Float32, here, p); !r) return r;
  const std::string_view extra = next_token(rest);
  if (!extra.empty()) {
    return error_here(
        fmt::format("vertex has more than 3 coordinates (unexpected {})", quote(extra)));
  }
  facet_vertices_.push_back(Vec3{p[0], p[1], p[2]});
  return {};
}

Result<void> AsciiStlParser::finish_facet() {
  const std::size_t n = facet_vertices_.size();
  if (n < 3) {
    ++skipped_facets_;
    tally_.add("stl.short_facet", Severity::Warning, facet_line_, [&] {
      return fmt::format("{}: facet has {} {}, so no area; skipped",
                         line_location(name_, facet_line_), n, n == 1 ? "vertex" : "vertices");
    });
    return {};
  }
  if (n > 3) {
    tally_.add("stl.polygon_facet", Severity::Warning, facet_line_, [&] {
      return fmt::format("{}: facet has {} vertices; triangulated as a fan of {} triangles",
                         line_location(name_, facet_line_), n, n - 2);
    });
  }
  if (soup_.triangles.size() + (n - 2) > limits_.max_triangles) {
    return bad_input(line_location(name_, facet_line_),
                     fmt::format("more than the limit of {} facets", limits_.max_triangles));
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    soup_.triangles.push_back({facet_vertices_[0], facet_vertices_[k], facet_vertices_[k + 1]});
    soup_.stored_normals.push_back(facet_normal_);
  }
  return {};
}

void AsciiStlParser::note_trailing(std::string_view keyword, std::string_view rest) {
  const std::string_view extra = trim(rest);
  if (extra.empty()) return;
  tally_.add("stl.trailing_tokens", Severity::Warning, lines_.number(), [&] {
    return fmt::format("{}: unexpected text {} after '{}' ignored",
                       line_location(name_, lines_.number()), quote(extra), keyword);
  });
}

Result<TriangleSoup> AsciiStlParser::parse() {
  soup_.format = "stl-ascii";
  State state = State::Top;
  std::size_t solids = 0;
  std::size_t solid_line = 0;
  std::string_view line;

  while (lines_.next(line)) {
    std::string_view rest = line;
    const std::string_view word = next_token(rest);
    if (word.empty()) continue;
    const Keyword keyword = classify(word);

    if (state == State::Top) {
      if (keyword == Keyword::Solid) {
        ++solids;
        solid_line = lines_.number();
        state = State::InSolid;
        continue;
      }
      if (keyword == Keyword::Facet && solids > 0) {
        tally_.add("stl.facet_outside_solid", Severity::Warning, lines_.number(), [&] {
          return fmt::format("{}: facets after 'endsolid' without a new 'solid' line; read anyway",
                             line_location(name_, lines_.number()));
        });
        state = State::InSolid;  // falls through to the facet below
      } else if (solids > 0) {
        // Some exporters pad the file after the last solid; nothing in it is a facet.
        const std::size_t ignored = text_.size() - (line.data() - text_.data());
        tally_.add("stl.content_after_endsolid", Severity::Warning, lines_.number(), [&] {
          return fmt::format("{}: {} bytes after the last 'endsolid' ignored (starting {})",
                             line_location(name_, lines_.number()), ignored, quote(line));
        });
        lines_.skip_rest();
        break;
      } else {
        return error_here(fmt::format("expected 'solid', found {}", quote(word)));
      }
    }

    if (state == State::InFacet) {
      switch (keyword) {
        case Keyword::Vertex:
          if (auto r = add_vertex(rest); !r) return r.error();
          continue;
        case Keyword::Outer: {
          const std::string_view loop = next_token(rest);
          if (!iequals_ascii(loop, "loop")) {
            note_trailing("outer",
                          std::string_view(loop.data(), line.data() + line.size() - loop.data()));
          } else {
            note_trailing("outer loop", rest);
          }
          continue;
        }
        case Keyword::EndLoop:
          note_trailing("endloop", rest);
          continue;
        case Keyword::EndFacet:
          note_trailing("endfacet", rest);
          if (auto r = finish_facet(); !r) return r.error();
          state = State::InSolid;
          continue;
        case Keyword::Facet:
        case Keyword::EndSolid:
        case Keyword::Solid:
          tally_.add("stl.missing_endfacet", Severity::Warning, facet_line_, [&] {
            return fmt::format("{}: facet has no 'endfacet' line; read up to line {}",
                               line_location(name_, facet_line_), lines_.number());
          });
          if (auto r = finish_facet(); !r) return r.error();
          state = State::InSolid;
          break;  // handled as in a solid below
        case Keyword::Other:
          return error_here(
              fmt::format("expected 'vertex', 'endloop' or 'endfacet', found {}", quote(word)));
      }
    }

    // state == State::InSolid
    switch (keyword) {
      case Keyword::Facet:
        if (!recognised_) {
          // Reserved only once the text is known to be ASCII STL, not for a binary file whose
          // header starts with "solid". About 250 bytes a facet in typical exporters' output.
          soup_.triangles.reserve(std::min(text_.size() / 256, limits_.max_triangles));
          soup_.stored_normals.reserve(soup_.triangles.capacity());
        }
        recognised_ = true;
        begin_facet(rest);
        state = State::InFacet;
        break;
      case Keyword::EndSolid:
        recognised_ = true;
        state = State::Top;
        break;
      case Keyword::Solid:
        tally_.add("stl.missing_endsolid", Severity::Warning, solid_line, [&] {
          return fmt::format("{}: solid has no 'endsolid' line", line_location(name_, solid_line));
        });
        ++solids;
        solid_line = lines_.number();
        break;
      case Keyword::Vertex:
      case Keyword::Outer:
      case Keyword::EndLoop:
      case Keyword::EndFacet:
        return error_here(fmt::format("{} outside a facet", quote(word)));
      case Keyword::Other:
        return error_here(fmt::format("expected 'facet' or 'endsolid', found {}", quote(word)));
    }
  }

  if (lines_.too_long()) {
    return bad_input(line_location(name_, lines_.number()),
                     fmt::format("line longer than the limit of {} bytes", limits_.max_line_bytes));
  }
  if (state == State::InFacet) {
    return bad_input(
        line_location(name_, lines_.number()),
        fmt::format("file ends inside the facet that starts at line {} (truncated?)", facet_line_));
  }
  if (state == State::InSolid) {
    tally_.add("stl.missing_endsolid", Severity::Warning, solid_line, [&] {
      return fmt::format("{}: solid has no 'endsolid' line (file ends at line {})",
                         line_location(name_, solid_line), lines_.number());
    });
  }
  if (soup_.triangles.empty()) {
    return bad_input(
        std::string(name_),
        skipped_facets_ == 0
            ? std::string("no facets: the file holds no facet")
            : fmt::format("no facets: all {} facets have fewer than 3 vertices", skipped_facets_));
  }
  if (solids > 1) {
    soup_.diagnostics.push_back(
        Diagnostic{Severity::Info, "stl.multiple_solids",
                   fmt::format("{}: {} solids in one file; all are read", name_, solids)});
  }
  tally_.flush_into(soup_.diagnostics);
  return std::move(soup_);
}

}  // namespace

namespace detail {

StlBinaryLayout stl_binary_layout(std::string_view bytes) {
  return stl_binary_layout(bytes, bytes.size());
}

StlBinaryLayout stl_binary_layout(std::string_view head, std::uint64_t size) {
  StlBinaryLayout layout;
  if (size < kStlBinaryHeaderBytes || head.size() < kStlBinaryHeaderBytes) return layout;
  const std::uint32_t count =
      detail::get_u32_le(reinterpret_cast<const unsigned char*>(head.data() + 80));
  layout.declared_facets = count;
  layout.expected_bytes =
      kStlBinaryHeaderBytes + std::uint64_t{kStlBinaryFacetBytes} * std::uint64_t{count};
  if (size == layout.expected_bytes) {
    layout.fit = StlBinaryFit::Exact;
  } else if (size > layout.expected_bytes && size - layout.expected_bytes < kStlBinaryFacetBytes) {
    layout.fit = StlBinaryFit::TrailingBytes;
    layout.trailing_bytes = size - layout.expected_bytes;
  } else {
    layout.fit = StlBinaryFit::Mismatch;
  }
  return layout;
}

bool starts_with_solid(std::string_view bytes) {
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  std::size_t i = 0;
  while (i < bytes.size() && (is_blank(bytes[i]) || bytes[i] == '\n' || bytes[i] == '\r')) ++i;
  return iequals_ascii(bytes.substr(i, 5), "solid") &&
         (i + 5 == bytes.size() || is_blank(bytes[i + 5]) || bytes[i + 5] == '\n' ||
          bytes[i + 5] == '\r');
}

}  // namespace detail

Result<TriangleSoup> read_stl_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits) {
  if (bytes.empty()) return bad_input(std::string(name), "empty file (0 bytes)");

  const StlBinaryLayout layout = detail::stl_binary_layout(bytes);
  if (layout.fit == StlBinaryFit::Exact || layout.fit == StlBinaryFit::TrailingBytes) {
    // In memory already: a block is a pointer into the bytes.
    const auto blocks = [bytes](std::uint32_t first, std::uint32_t, std::vector<char>&) {
      return bytes.data() + kStlBinaryHeaderBytes + std::size_t{first} * kStlBinaryFacetBytes;
    };
    return detail::read_stl_records(blocks, bytes.size(), name, layout, limits);
  }

  std::string ascii_note;
  if (detail::starts_with_solid(bytes)) {
    std::string_view text = bytes;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    AsciiStlParser parser(text, name, limits);
    Result<TriangleSoup> ascii = parser.parse();
    if (ascii || parser.recognised() || layout.fit == StlBinaryFit::TooShort) return ascii;
    // A binary file whose header happens to start with "solid": its size is the real problem.
    ascii_note = fmt::format("the file starts with 'solid' but is not ASCII STL either ({})",
                             ascii.error().to_string());
  }
  if (layout.fit == StlBinaryFit::TooShort) {
    return bad_input(std::string(name),
                     fmt::format("not an STL file: {} bytes is too short for a binary STL header "
                                 "(84 bytes) and the text does not start with 'solid'",
                                 bytes.size()));
  }
  return binary_size_error(bytes, name, layout, ascii_note);
}

}  // namespace strata::io
