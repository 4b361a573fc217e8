#include "strata/io/read_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/little_endian.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io {

namespace {

constexpr std::uint64_t kMaxLoadedCells = std::uint64_t{1} << 31;

Error bad_input(std::string location, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::move(location)};
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

/// Checks the values of a header read from either encoding; `where` locates the header.
Result<void> check_header_values(const CellsHeader& h, const std::string& where) {
  const GridSpec& g = h.grid;
  if (g.nx == 0 || g.ny == 0 || g.nz == 0) {
    return bad_input(where, fmt::format("grid {} x {} x {} has no cells; every size must be at "
                                        "least 1",
                                        g.nx, g.ny, g.nz));
  }
  if (!std::isfinite(g.x0) || !std::isfinite(g.y0) || !std::isfinite(g.z0)) {
    return bad_input(where, fmt::format("origin {} {} {} is not finite", g.x0, g.y0, g.z0));
  }
  if (!(std::isfinite(g.dx) && g.dx > 0) || !(std::isfinite(g.dy) && g.dy > 0) ||
      !(std::isfinite(g.dz) && g.dz > 0)) {
    return bad_input(where,
                     fmt::format("spacing {} {} {} must be positive and finite", g.dx, g.dy, g.dz));
  }
  if (!(std::isfinite(h.shell_mm) && h.shell_mm >= 0)) {
    return bad_input(where,
                     fmt::format("shell thickness {} must be finite and not negative", h.shell_mm));
  }
  return {};
}

// ----------------------------------------------------------------------------------- binary

Result<CellsHeader> read_binary(std::FILE* file, const std::filesystem::path& path,
                                std::uint64_t size, const CellsLayerVisitor& visit) {
  const std::string name = path.string();
  if (size < kCellsHeaderBytes) {
    return bad_input(name, fmt::format("file ends after {} bytes, inside the {}-byte header", size,
                                       kCellsHeaderBytes));
  }
  std::array<unsigned char, kCellsHeaderBytes> raw{};
  if (std::fread(raw.data(), 1, raw.size(), file) != raw.size()) {
    return bad_input(name, fmt::format("cannot read the header: {}", std::strerror(errno)));
  }
  const std::uint32_t header_bytes = detail::get_u32_le(raw.data() + 8);
  if (header_bytes != kCellsHeaderBytes) {
    return bad_input(name, fmt::format("header size field is {}; this version of the format has "
                                       "a {}-byte header",
                                       header_bytes, kCellsHeaderBytes));
  }
  CellsHeader h;
  h.encoding = CellsEncoding::Binary;
  GridSpec& g = h.grid;
  g.nx = detail::get_u32_le(raw.data() + 12);
  g.ny = detail::get_u32_le(raw.data() + 16);
  g.nz = detail::get_u32_le(raw.data() + 20);
  g.x0 = detail::get_f64_le(raw.data() + 24);
  g.y0 = detail::get_f64_le(raw.data() + 32);
  g.z0 = detail::get_f64_le(raw.data() + 40);
  g.dx = detail::get_f64_le(raw.data() + 48);
  g.dy = detail::get_f64_le(raw.data() + 56);
  g.dz = detail::get_f64_le(raw.data() + 64);
  h.shell_mm = detail::get_f64_le(raw.data() + 72);
  if (auto ok = check_header_values(h, name); !ok) return ok.error();

  const std::uint64_t layer_bytes = packed_layer_bytes(g);
  if (g.nz > (std::numeric_limits<std::uint64_t>::max() - kCellsHeaderBytes) / layer_bytes) {
    return bad_input(name,
                     fmt::format("grid {} x {} x {} is too large to address", g.nx, g.ny, g.nz));
  }
  const std::uint64_t expected = binary_cells_file_bytes(g);
  if (size != expected) {
    return bad_input(
        name,
        fmt::format("file is {} bytes, {} than the {} bytes a {} x {} x {} grid needs ({}-byte "
                    "header + {} layers of {} bytes)",
                    size, size < expected ? "shorter" : "longer", expected, g.nx, g.ny, g.nz,
                    kCellsHeaderBytes, g.nz, layer_bytes));
  }

  const std::uint64_t n = g.cells_per_layer();
  std::vector<unsigned char> packed(layer_bytes);
  std::vector<CellClass> cells(n);
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    if (std::fread(packed.data(), 1, packed.size(), file) != packed.size()) {
      return bad_input(fmt::format("{}: layer {}", name, k),
                       fmt::format("cannot read the layer: {}",
                                   std::ferror(file) ? std::strerror(errno) : "unexpected end"));
    }
    for (std::uint64_t idx = 0; idx < n; ++idx) {
      const unsigned code = (packed[idx / 4] >> (6 - 2 * (idx % 4))) & 0b11u;
      if (code == 0b10) {
        const std::uint64_t offset = kCellsHeaderBytes + k * layer_bytes + idx / 4;
        return bad_input(
            fmt::format("{}: layer {}, row {}, cell {}", name, k, idx / g.nx, idx % g.nx),
            fmt::format("reserved cell code 10 (byte {}); expected 00, 01 or 11", offset));
      }
      cells[idx] = static_cast<CellClass>(code);
    }
    if (const unsigned used = static_cast<unsigned>(n % 4); used != 0) {
      const unsigned padding_mask = 0xffu >> (2 * used);
      if ((packed.back() & padding_mask) != 0) {
        return bad_input(fmt::format("{}: layer {}", name, k),
                         fmt::format("the padding bits after the last cell of the layer (byte {}) "
                                     "are not zero",
                                     kCellsHeaderBytes + (k + 1) * layer_bytes - 1));
      }
    }
    if (auto ok = visit(h, k, cells); !ok) return ok.error();
  }
  return h;
}

// ------------------------------------------------------------------------------------ ascii

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t') ++pos;
    if (pos > start) words.push_back(line.substr(start, pos - start));
  }
  return words;
}

class LineReader {
 public:
  explicit LineReader(const std::filesystem::path& path)
      : in_(path, std::ios::binary), name_(path.string()) {}
  bool is_open() const { return in_.is_open(); }
  /// Reads the next line without its end (LF or CRLF); false at the end of the file.
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_no_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  std::string here() const { return fmt::format("{}:{}", name_, line_no_); }
  std::string after_last() const { return fmt::format("{}:{}", name_, line_no_ + 1); }

 private:
  std::ifstream in_;
  std::string name_;
  std::uint64_t line_no_ = 0;
};

/// A whole number of the header or a layer line, or the bad-number Error at the current line.
Result<std::uint32_t> scan_uint32(std::string_view word, const LineReader& in) {
  const ScannedNumber<std::uint64_t> scanned = scan_unsigned(word, NumberType::UInt32);
  if (!scanned.ok()) return bad_number(in.here(), word, scanned);
  return static_cast<std::uint32_t>(scanned.value);
}

/// A real number of the header or a layer line (read as double, as every text format but STL).
Result<double> scan_double(std::string_view word, const LineReader& in) {
  const ScannedNumber<double> scanned = scan_real(word);
  if (!scanned.ok()) return bad_number(in.here(), word, scanned);
  return scanned.value;
}

bool is_blank(std::string_view line) {
  return line.find_first_not_of(" \t") == std::string_view::npos;
}

Result<CellsHeader> read_ascii(const std::filesystem::path& path, std::uint64_t size,
                               const CellsLayerVisitor& visit) {
  LineReader in(path);
  if (!in.is_open()) {
    return bad_input(path.string(), fmt::format("cannot open the file: {}", std::strerror(errno)));
  }
  CellsHeader h;
  h.encoding = CellsEncoding::Ascii;
  GridSpec& g = h.grid;
  std::string line;

  if (!in.next(line) || split_words(line) != std::vector<std::string_view>{"strata-cells", "1"}) {
    const auto words = split_words(line);
    if (!words.empty() && words[0] == "strata-cells") {
      return bad_input(in.here(), fmt::format("unsupported version line '{}'; expected '{}'", line,
                                              kCellsAsciiFirstLine));
    }
    return bad_input(in.here(), fmt::format("expected the first line '{}'", kCellsAsciiFirstLine));
  }

  // Header: `key value...` lines in any order, each once, up to the first `layer` line.
  bool have_grid = false, have_origin = false, have_spacing = false, have_shell = false;
  bool at_layer = false;
  while (in.next(line)) {
    if (is_blank(line)) continue;
    const auto words = split_words(line);
    const std::string_view key = words[0];
    if (key == "layer") {
      at_layer = true;
      break;
    }
    auto expect = [&](bool& seen, std::size_t values, const char* shape) -> Result<void> {
      if (seen) return bad_input(in.here(), fmt::format("'{}' appears twice in the header", key));
      seen = true;
      if (words.size() != values + 1) {
        return bad_input(in.here(), fmt::format("expected '{}'", shape));
      }
      return {};
    };
    // Scans the key's values into their fields, stopping at the first bad one.
    auto read_values = [&](auto scan, auto... fields) -> Result<void> {
      std::size_t w = 1;
      for (auto* field : {fields...}) {
        const auto value = scan(words[w++], in);
        if (!value) return value.error();
        *field = *value;
      }
      return {};
    };
    if (key == "grid") {
      if (auto ok = expect(have_grid, 3, "grid nx ny nz"); !ok) return ok.error();
      if (auto ok = read_values(scan_uint32, &g.nx, &g.ny, &g.nz); !ok) return ok.error();
    } else if (key == "origin") {
      if (auto ok = expect(have_origin, 3, "origin x0 y0 z0"); !ok) return ok.error();
      if (auto ok = read_values(scan_double, &g.x0, &g.y0, &g.z0); !ok) return ok.error();
    } else if (key == "spacing") {
      if (auto ok = expect(have_spacing, 3, "spacing dx dy dz"); !ok) return ok.error();
      if (auto ok = read_values(scan_double, &g.dx, &g.dy, &g.dz); !ok) return ok.error();
    } else if (key == "shell") {
      if (auto ok = expect(have_shell, 1, "shell t"); !ok) return ok.error();
      if (auto ok = read_values(scan_double, &h.shell_mm); !ok) return ok.error();
    } else {
      return bad_input(in.here(), fmt::format("unknown header key '{}'; expected grid, origin, "
                                              "spacing, shell or the first 'layer' line",
                                              key));
    }
  }
  const char* missing = !have_grid      ? "grid"
                        : !have_origin  ? "origin"
                        : !have_spacing ? "spacing"
                        : !have_shell   ? "shell"
                                        : nullptr;
  if (missing != nullptr) {
    return bad_input(at_layer ? in.here() : in.after_last(),
                     fmt::format("the header has no '{}' line before the first layer", missing));
  }
  if (!at_layer) {
    return bad_input(in.after_last(),
                     fmt::format("file ends after the header; expected {} layers", g.nz));
  }
  if (auto ok = check_header_values(h, fmt::format("{}: header", path.string())); !ok) {
    return ok.error();
  }
  // Every cell takes two characters of the file. A header that promises more cells than the file
  // can hold is refused before a layer buffer (or a caller's per-layer storage) is sized from it:
  // a 100-byte file must not allocate gigabytes.
  const std::uint64_t layer_cells = g.cells_per_layer();
  if (layer_cells > size / 2 || g.nz > size / 2 / layer_cells) {
    return bad_input(fmt::format("{}: header", path.string()),
                     fmt::format("grid {} x {} x {} has more cells than a file of {} bytes holds "
                                 "at two characters a cell (truncated?)",
                                 g.nx, g.ny, g.nz, size));
  }

  const std::size_t row_chars = std::size_t{g.nx} * 2;
  std::vector<CellClass> cells(g.cells_per_layer());
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    if (k > 0) {
      // Blank lines between layers are tolerated.
      bool found = false;
      while (in.next(line)) {
        if (!is_blank(line)) {
          found = true;
          break;
        }
      }
      if (!found) {
        return bad_input(in.after_last(), fmt::format("file ends after {} of {} layers", k, g.nz));
      }
    }
    const auto words = split_words(line);
    if (words.size() != 3 || words[0] != "layer" || words[2].substr(0, 2) != "z=") {
      return bad_input(in.here(), fmt::format("expected 'layer {} z=<number>'", k));
    }
    const Result<std::uint32_t> index = scan_uint32(words[1], in);
    if (!index) return index.error();
    if (const Result<double> z = scan_double(words[2].substr(2), in); !z) return z.error();
    if (*index != k) {
      return bad_input(in.here(),
                       fmt::format("layer {} found where layer {} was expected", *index, k));
    }
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      if (!in.next(line)) {
        return bad_input(in.after_last(),
                         fmt::format("file ends inside layer {}: {} of {} rows", k, j, g.ny));
      }
      if (line.size() != row_chars) {
        return bad_input(in.here(),
                         fmt::format("row {} of layer {} has {} characters; expected {} ({} cells "
                                     "of two characters)",
                                     j, k, line.size(), row_chars, g.nx));
      }
      CellClass* row = cells.data() + std::uint64_t{j} * g.nx;
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        const char hi = line[2 * std::size_t{i}];
        const char lo = line[2 * std::size_t{i} + 1];
        if (hi == '0' && lo == '0') {
          row[i] = CellClass::Empty;
        } else if (hi == '0' && lo == '1') {
          row[i] = CellClass::Interior;
        } else if (hi == '1' && lo == '1') {
          row[i] = CellClass::Boundary;
        } else if (hi == '1' && lo == '0') {
          return bad_input(in.here(), fmt::format("reserved cell code 10 at layer {}, row {}, cell "
                                                  "{} (column {}); expected 00, 01 or 11",
                                                  k, j, i, 2 * std::uint64_t{i} + 1));
        } else {
          return bad_input(in.here(),
                           fmt::format("'{}{}' at layer {}, row {}, cell {} (column {}) is not a "
                                       "cell code; expected 00, 01 or 11",
                                       hi, lo, k, j, i, 2 * std::uint64_t{i} + 1));
        }
      }
    }
    if (auto ok = visit(h, k, cells); !ok) return ok.error();
  }
  while (in.next(line)) {
    if (!is_blank(line)) {
      return bad_input(in.here(),
                       fmt::format("unexpected content after the last of {} layers", g.nz));
    }
  }
  return h;
}

}  // namespace

Result<CellsHeader> read_cells_layers(const std::filesystem::path& path,
                                      const CellsLayerVisitor& visit) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return bad_input(name, "is a folder, not a cells file");
  }
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return bad_input(name, fmt::format("cannot read the file: {}", ec.message()));
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) return bad_input(name, fmt::format("cannot open the file: {}", std::strerror(errno)));

  std::array<char, 16> start{};
  const std::size_t got = std::fread(start.data(), 1, start.size(), file.get());
  const std::string_view head(start.data(), got);
  if (head.substr(0, kCellsMagic.size()) == kCellsMagic) {
    std::rewind(file.get());
    return read_binary(file.get(), path, size, visit);
  }
  constexpr std::string_view kAsciiWord = "strata-cells";
  if (head.substr(0, kAsciiWord.size()) == kAsciiWord) {
    file.reset();
    return read_ascii(path, size, visit);
  }
  if (size < kCellsMagic.size()) {
    return bad_input(name, fmt::format("file of {} bytes is too short to be a cells file", size));
  }
  return bad_input(name, fmt::format("not a cells file: it starts neither with the magic '{}' "
                                     "(binary) nor with the line '{}' (ASCII)",
                                     kCellsMagic, kCellsAsciiFirstLine));
}

Result<CellsFile> read_cells(const std::filesystem::path& path) {
  CellsFile result;
  auto header = read_cells_layers(
      path,
      [&](const CellsHeader& h, std::uint32_t k, std::span<const CellClass> cells) -> Result<void> {
        if (k == 0) {
          const std::uint64_t total = h.grid.cell_count();
          if (h.grid.cells_per_layer() > kMaxLoadedCells || total > kMaxLoadedCells) {
            return bad_input(path.string(),
                             fmt::format("{} x {} x {} cells are too many to load at once",
                                         h.grid.nx, h.grid.ny, h.grid.nz));
          }
          result.cells.reserve(total);
        }
        result.cells.insert(result.cells.end(), cells.begin(), cells.end());
        return {};
      });
  if (!header) return header.error();
  result.header = *header;
  return result;
}

Result<CellsSummary> summarize_cells(const std::filesystem::path& path) {
  CellsSummary summary;
  auto header = read_cells_layers(
      path,
      [&](const CellsHeader& h, std::uint32_t k, std::span<const CellClass> cells) -> Result<void> {
        if (k == 0) summary.layer_counts.reserve(h.grid.nz);
        std::array<std::uint64_t, 3> counts{};
        bool any_solid = false;
        std::uint32_t i_min = h.grid.nx, i_max = 0, j_min = h.grid.ny, j_max = 0;
        for (std::uint32_t j = 0; j < h.grid.ny; ++j) {
          const CellClass* row = cells.data() + std::uint64_t{j} * h.grid.nx;
          for (std::uint32_t i = 0; i < h.grid.nx; ++i) {
            switch (row[i]) {
              case CellClass::Empty:
                ++counts[0];
                continue;
              case CellClass::Interior:
                ++counts[1];
                break;
              case CellClass::Boundary:
                ++counts[2];
                break;
            }
            any_solid = true;
            i_min = std::min(i_min, i);
            i_max = std::max(i_max, i);
            j_min = std::min(j_min, j);
            j_max = std::max(j_max, j);
          }
        }
        for (int c = 0; c < 3; ++c) summary.class_counts[c] += counts[c];
        summary.layer_counts.push_back(counts);
        if (any_solid) {
          if (!summary.solid_bounds) {
            summary.solid_bounds = CellIndexBox{i_min, i_max, j_min, j_max, k, k};
          } else {
            CellIndexBox& b = *summary.solid_bounds;
            b.i_min = std::min(b.i_min, i_min);
            b.i_max = std::max(b.i_max, i_max);
            b.j_min = std::min(b.j_min, j_min);
            b.j_max = std::max(b.j_max, j_max);
            b.k_max = k;
          }
        }
        return {};
      });
  if (!header) return header.error();
  summary.header = *header;
  return summary;
}

}  // namespace strata::io
