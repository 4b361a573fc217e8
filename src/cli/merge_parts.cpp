#include "cli/merge_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>

#include "strata/io/cells_format.hpp"
#include "strata/io/output_file.hpp"
#include "strata/slice/layer_range.hpp"

namespace strata::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::size_t kCopyBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxOpenChainReports = 1000;  // as many as a slice report lists
constexpr std::string_view kCliAsciiHeaderEnd = "$$HEADEREND\n$$GEOMETRYSTART\n";
constexpr std::string_view kCliBinaryHeaderEnd = "$$HEADEREND";
constexpr std::string_view kCliAsciiTrailer = "$$GEOMETRYEND\n";

/// One part as its report describes it.
struct Part {
  fs::path dir;
  std::string stem;
  LayerSpan range;
  std::uint32_t nz_total = 0;
  std::string fingerprint;
  std::set<std::string> formats;
  json report;
};

Error bad(const fs::path& where, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), where.string()};
}

Result<std::string> read_bytes(const fs::path& path, std::uint64_t offset, std::uint64_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return bad(path, "cannot be read");
  in.seekg(static_cast<std::streamoff>(offset));
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  if (static_cast<std::uint64_t>(in.gcount()) != count) return bad(path, "ends too early");
  return bytes;
}

bool is_layer_report(const json& j) {
  return j.is_object() && j.contains("range") && j.contains("fingerprint") && j.contains("formats");
}

/// The first field the merge reads that `report` lacks (or holds with another type); nullptr
/// when it has them all.
const char* first_missing_field(const json& report) {
  enum class Kind { Unsigned, Number, String, Array, Object };
  static const std::pair<const char*, Kind> kFields[] = {
      {"/range/first", Kind::Unsigned},
      {"/range/end", Kind::Unsigned},
      {"/range/nz_total", Kind::Unsigned},
      {"/fingerprint", Kind::String},
      {"/formats", Kind::Array},
      {"/grid/spacing_mm", Kind::Array},
      {"/cells/empty", Kind::Unsigned},
      {"/cells/interior", Kind::Unsigned},
      {"/cells/boundary", Kind::Unsigned},
      {"/metrics/mesh_volume_mm3", Kind::Number},
      {"/metrics/segments", Kind::Unsigned},
      {"/metrics/exact_fallbacks", Kind::Unsigned},
      {"/metrics/crossing_loop_layers", Kind::Unsigned},
      {"/metrics/misnested_loop_layers", Kind::Unsigned},
      {"/metrics/outline_layers", Kind::Unsigned},
      {"/open_chains/count", Kind::Unsigned},
      {"/open_chains/first", Kind::Array},
      {"/layers", Kind::Array},
      {"/diagnostics", Kind::Array},
      {"/timings_s", Kind::Object},
  };
  for (const auto& [pointer, kind] : kFields) {
    const json::json_pointer at(pointer);
    if (!report.contains(at)) return pointer;
    const json& v = report.at(at);
    const bool ok = kind == Kind::Unsigned ? v.is_number_unsigned()
                    : kind == Kind::Number ? v.is_number()
                    : kind == Kind::String ? v.is_string()
                    : kind == Kind::Array  ? v.is_array()
                                           : v.is_object();
    if (!ok) return pointer;
  }
  const json& spacing = report.at(json::json_pointer("/grid/spacing_mm"));
  if (spacing.size() != 3 || !spacing[0].is_number() || !spacing[1].is_number() ||
      !spacing[2].is_number()) {
    return "/grid/spacing_mm";
  }
  for (const json& layer : report.at("layers")) {
    if (!layer.is_object() || !layer.contains("contour_area_mm2") || !layer.contains("interior") ||
        !layer.contains("boundary") || !layer["contour_area_mm2"].is_number() ||
        !layer["interior"].is_number_unsigned() || !layer["boundary"].is_number_unsigned()) {
      return "/layers";
    }
  }
  for (const auto& [key, value] : report.at("timings_s").items()) {
    if (!value.is_number()) return "/timings_s";
  }
  return nullptr;
}

Result<Part> read_part(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return bad(dir, "not a folder of slice outputs");
  std::vector<fs::path> reports;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (p.extension() != ".json" || !it->is_regular_file(ec)) continue;
    std::ifstream in(p, std::ios::binary);
    const json j = json::parse(in, nullptr, false);
    if (!j.is_discarded() && is_layer_report(j)) reports.push_back(p);
  }
  if (reports.empty()) {
    return bad(dir,
               "no slice report with a layer range in it: slice every part with the json "
               "format (the report carries the part's range and fingerprint)");
  }
  if (reports.size() > 1) {
    return bad(dir, fmt::format("more than one slice report in it ({}, {}): one part a folder",
                                reports[0].filename().string(), reports[1].filename().string()));
  }
  Part part;
  part.dir = dir;
  part.stem = reports[0].stem().string();
  std::ifstream in(reports[0], std::ios::binary);
  part.report = json::parse(in, nullptr, false);
  const json& r = part.report;
  if (const char* missing = first_missing_field(r)) {
    return bad(
        reports[0],
        fmt::format("not a slice report of this version: {} is missing or malformed", missing));
  }
  const json& range = r["range"];
  part.range = {range["first"].get<std::uint32_t>(), range["end"].get<std::uint32_t>()};
  part.nz_total = range["nz_total"].get<std::uint32_t>();
  if (part.range.end <= part.range.first || part.range.end > part.nz_total ||
      r["layers"].size() != part.range.count()) {
    return bad(reports[0], fmt::format("the range {}:{} of {} layers does not fit its report",
                                       part.range.first, part.range.end, part.nz_total));
  }
  part.fingerprint = r["fingerprint"].get<std::string>();
  for (const json& f : r["formats"]) {
    if (!f.is_string()) return bad(reports[0], "a format is not a name");
    part.formats.insert(f.get<std::string>());
  }
  return part;
}

std::string layer_list(const std::vector<LayerSpan>& spans) {
  std::string out;
  for (const LayerSpan& s : spans) {
    if (!out.empty()) out += ", ";
    out += s.count() == 1 ? fmt::format("{}", s.first) : fmt::format("{}..{}", s.first, s.end - 1);
  }
  return out;
}

/// Parts sharing one run and tiling its layers, sorted by first layer; or why not.
Result<std::vector<Part>> check_parts(std::vector<Part> parts) {
  const Part& ref = parts.front();
  for (const Part& p : parts) {
    if (p.fingerprint != ref.fingerprint) {
      return bad(p.dir, fmt::format("sliced from another model or with other options than {} "
                                    "(fingerprint {:.12} against {:.12})",
                                    ref.dir.string(), p.fingerprint, ref.fingerprint));
    }
    if (p.stem != ref.stem) {
      return bad(p.dir, fmt::format("its outputs are named {}, those of {} {}", p.stem,
                                    ref.dir.string(), ref.stem));
    }
    if (p.nz_total != ref.nz_total) {
      return bad(p.dir, fmt::format("its model has {} layers, that of {} {}", p.nz_total,
                                    ref.dir.string(), ref.nz_total));
    }
    if (p.formats != ref.formats) {
      return bad(p.dir, fmt::format("holds the outputs {}, {} holds {}", fmt::join(p.formats, ","),
                                    ref.dir.string(), fmt::join(ref.formats, ",")));
    }
  }
  std::stable_sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) {
    return a.range.first != b.range.first ? a.range.first < b.range.first
                                          : a.range.end < b.range.end;
  });
  std::vector<LayerSpan> missing;
  std::uint32_t covered = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts[i];
    if (i > 0 && p.range.first < parts[i - 1].range.end) {
      const Part& q = parts[i - 1];
      return bad(p.dir,
                 fmt::format("its layers {}..{} overlap those of {} ({}..{})", p.range.first,
                             p.range.end - 1, q.dir.string(), q.range.first, q.range.end - 1));
    }
    if (p.range.first > covered) missing.push_back({covered, p.range.first});
    covered = p.range.end;
  }
  if (covered < ref.nz_total) missing.push_back({covered, ref.nz_total});
  if (!missing.empty()) {
    std::string slices;
    for (const LayerSpan& s : missing) {
      slices += fmt::format("{}--layers {}:{}", slices.empty() ? "" : ", ", s.first, s.end);
    }
    return Error{ErrorCode::BadInput,
                 fmt::format("the parts leave out layers {} of the model's {} (0..{}): slice "
                             "them with {}",
                             layer_list(missing), ref.nz_total, ref.nz_total - 1, slices),
                 {}};
  }
  return parts;
}

/// Where a part's single-file output of `format` lives.
fs::path single_file(const Part& p, const std::string& format) {
  if (format == "cells") return p.dir / (p.stem + ".cells");
  if (format == "cells-ascii") return p.dir / (p.stem + ".cells.txt");
  if (format == "cli") return p.dir / (p.stem + ".cli");
  return p.dir / (p.stem + ".bin.cli");
}

fs::path layer_file(const fs::path& dir, const std::string& stem, const char* kind,
                    std::uint32_t k) {
  return dir / kind / fmt::format("{}_{:05}.{}", stem, k, kind);
}

/// The header of a part's cells file, checked against the part's range and the first part.
Result<std::string> checked_cells_header(const Part& p, const std::string& first_header) {
  const fs::path path = single_file(p, "cells");
  auto header = read_bytes(path, 0, io::kCellsHeaderBytes);
  if (!header) return header.error();
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int b = 3; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>((*header)[at + b]);
    return v;
  };
  if (header->compare(0, io::kCellsMagic.size(), io::kCellsMagic) != 0 ||
      u32(8) != io::kCellsHeaderBytes) {
    return bad(path, "not a cells file of this version");
  }
  if (u32(20) != p.range.count()) {
    return bad(path, fmt::format("holds {} layers, its report says {}", u32(20), p.range.count()));
  }
  // nx, ny (12..19) and x0, y0 (24..39), the spacing and the shell (48..79) are the run's.
  if (!first_header.empty() && (header->compare(12, 8, first_header, 12, 8) != 0 ||
                                header->compare(24, 16, first_header, 24, 16) != 0 ||
                                header->compare(48, 32, first_header, 48, 32) != 0)) {
    return bad(path, "its grid is not that of the other parts");
  }
  const std::uint64_t layer_bytes = (std::uint64_t{u32(12)} * u32(16) + 3) / 4;
  std::error_code ec;
  const std::uint64_t size = fs::file_size(path, ec);
  if (ec || size != io::kCellsHeaderBytes + layer_bytes * p.range.count()) {
    return bad(path, fmt::format("is {} bytes long; its header asks for {}", ec ? 0 : size,
                                 io::kCellsHeaderBytes + layer_bytes * p.range.count()));
  }
  return header;
}

/// A CLI file split into its header (through the geometry start) and its layer commands.
struct CliPieces {
  std::string header;
  std::uint64_t body_begin = 0;
  std::uint64_t body_end = 0;
};

Result<CliPieces> split_cli(const fs::path& path, bool binary) {
  std::error_code ec;
  const std::uint64_t size = fs::file_size(path, ec);
  if (ec) return bad(path, "cannot be read");
  auto head = read_bytes(path, 0, std::min<std::uint64_t>(size, 1 << 16));
  if (!head) return head.error();
  const std::string_view end_mark = binary ? kCliBinaryHeaderEnd : kCliAsciiHeaderEnd;
  const std::size_t at = head->find(end_mark);
  if (head->rfind("$$HEADERSTART", 0) != 0 || at == std::string::npos) {
    return bad(path, "not a CLI file as strata writes it (no header end)");
  }
  CliPieces pieces;
  pieces.header = head->substr(0, at + end_mark.size());
  pieces.body_begin = at + end_mark.size();
  pieces.body_end = size;
  if (!binary) {
    auto tail = read_bytes(path, size - std::min<std::uint64_t>(size, kCliAsciiTrailer.size()),
                           std::min<std::uint64_t>(size, kCliAsciiTrailer.size()));
    if (!tail || *tail != kCliAsciiTrailer || size < pieces.body_begin + kCliAsciiTrailer.size()) {
      return bad(path, "does not end with $$GEOMETRYEND");
    }
    pieces.body_end = size - kCliAsciiTrailer.size();
  }
  return pieces;
}

/// The header line that starts with `key`, its value (the rest of the line).
std::string_view header_value(std::string_view header, std::string_view key) {
  const std::size_t at = header.find(key);
  if (at == std::string_view::npos) return {};
  const std::size_t begin = at + key.size();
  return header.substr(begin, header.find('\n', begin) - begin);
}

/// The merged CLI header: the first part's, spanning up to the last part's top, of all layers.
Result<std::string> merged_cli_header(const fs::path& first_path, std::string header,
                                      std::string_view last_header, std::uint32_t nz_total) {
  const std::string_view first_dim = header_value(header, "$$DIMENSION/");
  const std::string_view last_dim = header_value(last_header, "$$DIMENSION/");
  const std::size_t first_cut = first_dim.rfind(',');
  const std::size_t last_cut = last_dim.rfind(',');
  const std::string_view layers = header_value(header, "$$LAYERS/");
  if (first_cut == std::string_view::npos || last_cut == std::string_view::npos || layers.empty()) {
    return bad(first_path, "its header has no $$DIMENSION or $$LAYERS");
  }
  const std::string dim =
      std::string(first_dim.substr(0, first_cut)) + std::string(last_dim.substr(last_cut));
  const std::size_t dim_size = first_dim.size();
  const std::size_t layers_size = layers.size();
  // The views above point into `header`: every length is taken before it changes.
  header.replace(header.find("$$DIMENSION/") + 12, dim_size, dim);
  header.replace(header.find("$$LAYERS/") + 9, layers_size, std::to_string(nz_total));
  return header;
}

/// What the merge has written so far, removed again when a later step fails.
class Written {
 public:
  Written() = default;
  ~Written() {
    if (!kept_) remove();
  }
  Written(const Written&) = delete;
  Written& operator=(const Written&) = delete;

  Result<void> ensure_directory(const fs::path& dir) {
    std::error_code ec;
    if (fs::is_directory(dir, ec)) return {};
    if (!fs::create_directories(dir, ec) || ec) {
      return bad(dir, fmt::format("cannot create the output folder: {}", ec.message()));
    }
    dirs_.push_back(dir);
    return {};
  }
  /// Opens `path` for writing under a temporary name.
  Result<io::OutputFile> open(const fs::path& path) {
    if (auto ok = ensure_directory(path.parent_path()); !ok) return ok.error();
    return io::OutputFile::create(path);
  }
  Result<void> commit(io::OutputFile& file) {
    if (auto ok = file.commit(); !ok) return ok;
    files_.push_back(file.path());
    return {};
  }
  void keep() { kept_ = true; }

 private:
  void remove() noexcept {
    std::error_code ec;
    for (const fs::path& f : files_) fs::remove(f, ec);
    for (auto it = dirs_.rbegin(); it != dirs_.rend(); ++it) fs::remove(*it, ec);
  }

  std::vector<fs::path> files_;
  std::vector<fs::path> dirs_;  ///< created, parents first
  bool kept_ = false;
};

/// Appends bytes [begin, end) of `path` to `out`.
Result<void> copy_bytes(const fs::path& path, std::uint64_t begin, std::uint64_t end,
                        io::OutputFile& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return bad(path, "cannot be read");
  in.seekg(static_cast<std::streamoff>(begin));
  std::string buffer(kCopyBytes, '\0');
  for (std::uint64_t at = begin; at < end;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kCopyBytes, end - at));
    in.read(buffer.data(), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(in.gcount()) != n) return bad(path, "ends too early");
    out.write(std::string_view(buffer.data(), n));
    at += n;
  }
  return {};
}

Result<void> merge_cells(const std::vector<Part>& parts, const fs::path& out_dir,
                         Written& written) {
  std::string first_header;
  for (const Part& p : parts) {
    auto header = checked_cells_header(p, first_header);
    if (!header) return header.error();
    if (first_header.empty()) first_header = std::move(*header);
  }
  // The first part starts at layer 0, so its z0 is the whole run's; nz becomes the total.
  for (int b = 0; b < 4; ++b) {
    first_header[20 + b] = static_cast<char>((parts.front().nz_total >> (8 * b)) & 0xff);
  }
  auto out = written.open(out_dir / (parts.front().stem + ".cells"));
  if (!out) return out.error();
  out->write(first_header);
  for (const Part& p : parts) {
    const fs::path path = single_file(p, "cells");
    if (auto ok = copy_bytes(path, io::kCellsHeaderBytes, fs::file_size(path), *out); !ok)
      return ok;
  }
  return written.commit(*out);
}

Result<void> merge_cells_ascii(const std::vector<Part>& parts, const fs::path& out_dir,
                               Written& written) {
  constexpr int kHeaderLines = 5;  // strata-cells, grid, origin, spacing, shell
  auto out = written.open(out_dir / (parts.front().stem + ".cells.txt"));
  if (!out) return out.error();
  std::string line;
  std::string grid_line;
  for (const Part& p : parts) {
    const fs::path path = single_file(p, "cells-ascii");
    std::ifstream in(path, std::ios::binary);
    if (!in) return bad(path, "cannot be read");
    for (int h = 0; h < kHeaderLines; ++h) {
      if (!std::getline(in, line)) return bad(path, "ends inside its header");
      if (h == 1) {
        const std::size_t cut = line.rfind(' ');
        if (line.rfind("grid ", 0) != 0 || cut == std::string::npos ||
            line.substr(cut + 1) != std::to_string(p.range.count())) {
          return bad(path, fmt::format("its grid line '{}' does not hold the report's {} layers",
                                       line, p.range.count()));
        }
        if (grid_line.empty()) grid_line = line.substr(0, cut);
        if (line.substr(0, cut) != grid_line) {
          return bad(path, "its grid is not that of the other parts");
        }
        line = fmt::format("{} {}", grid_line, p.nz_total);
      }
      if (&p == &parts.front()) out->write(line + "\n");
    }
    std::uint32_t layers = 0;
    while (std::getline(in, line)) {
      if (line.rfind("layer ", 0) == 0) {
        // "layer <k> z=<z>": k counts from the part's first layer; z is the whole run's already.
        const std::size_t space = line.find(' ', 6);
        if (space == std::string::npos || line.substr(6, space - 6) != std::to_string(layers)) {
          return bad(path, fmt::format("expected 'layer {} z=...', found '{}'", layers, line));
        }
        line = fmt::format("layer {}{}", p.range.first + layers, line.substr(space));
        ++layers;
      }
      out->write(line);
      out->write("\n");
    }
    if (layers != p.range.count()) {
      return bad(path, fmt::format("holds {} layers, its report says {}", layers, p.range.count()));
    }
  }
  return written.commit(*out);
}

Result<void> merge_cli(const std::vector<Part>& parts, const std::string& format,
                       const fs::path& out_dir, Written& written) {
  const bool binary = format == "cli-binary";
  std::vector<CliPieces> pieces;
  for (const Part& p : parts) {
    auto split = split_cli(single_file(p, format), binary);
    if (!split) return split.error();
    pieces.push_back(std::move(*split));
  }
  const fs::path first_path = single_file(parts.front(), format);
  auto header = merged_cli_header(first_path, pieces.front().header, pieces.back().header,
                                  parts.front().nz_total);
  if (!header) return header.error();
  auto out = written.open(out_dir / single_file(parts.front(), format).filename());
  if (!out) return out.error();
  out->write(*header);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const fs::path path = single_file(parts[i], format);
    if (auto ok = copy_bytes(path, pieces[i].body_begin, pieces[i].body_end, *out); !ok) return ok;
  }
  if (!binary) out->write(kCliAsciiTrailer);
  return written.commit(*out);
}

Result<void> check_layer_files(const std::vector<Part>& parts, const char* kind) {
  for (const Part& p : parts) {
    for (std::uint32_t k = p.range.first; k < p.range.end; ++k) {
      std::error_code ec;
      const fs::path file = layer_file(p.dir, p.stem, kind, k);
      if (!fs::is_regular_file(file, ec)) return bad(file, "missing: the part is incomplete");
    }
  }
  return {};
}

Result<void> copy_layer_files(const std::vector<Part>& parts, const char* kind,
                              const fs::path& out_dir, Written& written) {
  for (const Part& p : parts) {
    for (std::uint32_t k = p.range.first; k < p.range.end; ++k) {
      const fs::path from = layer_file(p.dir, p.stem, kind, k);
      auto out = written.open(layer_file(out_dir, p.stem, kind, k));
      if (!out) return out.error();
      std::error_code ec;
      if (auto ok = copy_bytes(from, 0, fs::file_size(from, ec), *out); !ok) return ok;
      if (auto ok = written.commit(*out); !ok) return ok;
    }
  }
  return {};
}

/// The whole run's report from the parts' (see merge_parts for what is recomputed).
json merged_report(const std::vector<Part>& parts) {
  json m = parts.front().report;
  const std::uint32_t nz_total = parts.front().nz_total;
  m["range"] = {{"first", 0}, {"end", nz_total}, {"nz_total", nz_total}};
  m.erase("plan");

  const json& spacing = m["grid"]["spacing_mm"];
  const double dx = spacing[0].get<double>();
  const double dy = spacing[1].get<double>();
  const double dz = spacing[2].get<double>();
  std::uint64_t empty = 0, interior = 0, boundary = 0;
  std::uint64_t segments = 0, fallbacks = 0, crossing = 0, misnested = 0, outline = 0;
  std::uint64_t open_chains = 0;
  json layers = json::array();
  json chains = json::array();
  json diagnostics = json::array();
  json timings = json::object();
  json merged_from = json::array();
  for (const Part& p : parts) {
    const json& r = p.report;  // read_part checked every field read here
    empty += r["cells"]["empty"].get<std::uint64_t>();
    interior += r["cells"]["interior"].get<std::uint64_t>();
    boundary += r["cells"]["boundary"].get<std::uint64_t>();
    const json& metrics = r["metrics"];
    segments += metrics["segments"].get<std::uint64_t>();
    fallbacks += metrics["exact_fallbacks"].get<std::uint64_t>();
    crossing += metrics["crossing_loop_layers"].get<std::uint64_t>();
    misnested += metrics["misnested_loop_layers"].get<std::uint64_t>();
    outline += metrics["outline_layers"].get<std::uint64_t>();
    open_chains += r["open_chains"]["count"].get<std::uint64_t>();
    for (const json& c : r["open_chains"]["first"]) {
      if (chains.size() < kMaxOpenChainReports) chains.push_back(c);
    }
    for (const json& l : r["layers"]) layers.push_back(l);
    for (const json& d : r["diagnostics"]) {
      if (std::find(diagnostics.begin(), diagnostics.end(), d) == diagnostics.end()) {
        diagnostics.push_back(d);
      }
    }
    for (const auto& [key, value] : r["timings_s"].items()) {
      timings[key] = timings.value(key, 0.0) + value.get<double>();
    }
    merged_from.push_back(
        {{"dir", p.dir.string()}, {"first", p.range.first}, {"end", p.range.end}});
  }
  // As the slicer sums them: layer by layer, in order, so the doubles are the whole run's.
  const double solid = static_cast<double>(interior + boundary) * dx * dy * dz;
  double contour_volume = 0.0;
  std::uint64_t empty_inside = 0, gap = 0;
  bool seen_solid = false;
  for (const json& l : layers) {
    contour_volume += l["contour_area_mm2"].get<double>() * dz;
    if (l["interior"].get<std::uint64_t>() + l["boundary"].get<std::uint64_t>() > 0) {
      if (seen_solid) empty_inside += gap;
      seen_solid = true;
      gap = 0;
    } else if (seen_solid) {
      ++gap;
    }
  }
  m["cells"] = {{"empty", empty},
                {"interior", interior},
                {"boundary", boundary},
                {"solid_volume_mm3", solid}};
  json& metrics = m["metrics"];
  const double mesh_volume = metrics["mesh_volume_mm3"].get<double>();
  metrics["cell_volume_mm3"] = solid;
  metrics["contour_volume_mm3"] = contour_volume;
  metrics["cell_volume_relative_error"] =
      mesh_volume != 0.0 ? (solid - mesh_volume) / std::fabs(mesh_volume) : 0.0;
  metrics["segments"] = segments;
  metrics["exact_fallbacks"] = fallbacks;
  metrics["crossing_loop_layers"] = crossing;
  metrics["misnested_loop_layers"] = misnested;
  metrics["outline_layers"] = outline;
  m["open_chains"] = {{"count", open_chains}, {"first", chains}};
  m["layers"] = layers;
  m["empty_layers_inside_model"] = empty_inside;
  m["diagnostics"] = diagnostics;
  m["timings_s"] = timings;
  m["merged_from"] = merged_from;
  return m;
}

/// Whether writing into `out_dir` could replace a part's own files.
bool is_a_part(const fs::path& out_dir, const std::vector<Part>& parts) {
  std::error_code ec;
  for (const Part& p : parts) {
    if (fs::exists(out_dir, ec) && fs::equivalent(out_dir, p.dir, ec)) return true;
  }
  return false;
}

}  // namespace

Result<MergeOutcome> merge_parts(const std::vector<fs::path>& part_dirs, const fs::path& out_dir) {
  if (part_dirs.empty()) return Error{ErrorCode::Usage, "no part to merge", {}};
  std::vector<Part> read;
  for (const fs::path& dir : part_dirs) {
    auto part = read_part(dir);
    if (!part) return part.error();
    read.push_back(std::move(*part));
  }
  auto checked = check_parts(std::move(read));
  if (!checked) return checked.error();
  const std::vector<Part>& parts = *checked;
  if (is_a_part(out_dir, parts)) {
    return Error{ErrorCode::Usage, "the output folder is one of the parts; merge into another",
                 out_dir.string()};
  }
  std::error_code ec;
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec)) {
    return Error{ErrorCode::Usage, "the output path exists and is not a folder", out_dir.string()};
  }
  const std::set<std::string>& formats = parts.front().formats;
  // Every part's files are there before anything is written.
  for (const std::string& format : formats) {
    if (format == "png" || format == "svg") {
      if (auto ok = check_layer_files(parts, format.c_str()); !ok) return ok.error();
    } else if (format != "json" && format != "html") {
      for (const Part& p : parts) {
        const fs::path file = single_file(p, format);
        if (!fs::is_regular_file(file, ec)) return bad(file, "missing: the part is incomplete");
      }
    }
  }

  MergeOutcome outcome;
  outcome.stem = parts.front().stem;
  outcome.nz_total = parts.front().nz_total;
  outcome.parts = parts.size();
  const std::string& stem = outcome.stem;
  Written written;
  if (auto ok = written.ensure_directory(out_dir); !ok) return ok.error();
  for (const std::string& format : formats) {
    Result<void> ok;
    if (format == "cells") {
      ok = merge_cells(parts, out_dir, written);
      outcome.written.push_back(stem + ".cells");
    } else if (format == "cells-ascii") {
      ok = merge_cells_ascii(parts, out_dir, written);
      outcome.written.push_back(stem + ".cells.txt");
    } else if (format == "png" || format == "svg") {
      ok = copy_layer_files(parts, format.c_str(), out_dir, written);
      outcome.written.push_back(fmt::format("{}/ ({} layers)", format, outcome.nz_total));
    } else if (format == "cli" || format == "cli-binary") {
      ok = merge_cli(parts, format, out_dir, written);
      outcome.written.push_back(single_file(parts.front(), format).filename().string());
    } else {
      continue;  // the report is written last; a part never holds a view page
    }
    if (!ok) return ok.error();
  }
  if (formats.count("json")) {
    auto out = written.open(out_dir / (stem + ".json"));
    if (!out) return out.error();
    out->write(merged_report(parts).dump(2) + "\n");
    if (auto ok = written.commit(*out); !ok) return ok.error();
    outcome.written.push_back(stem + ".json");
  }
  written.keep();
  return outcome;
}

}  // namespace strata::cli
