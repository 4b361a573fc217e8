#include "models.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include "degenerate_models.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/io/write_stl.hpp"

namespace strata::validation {
namespace {

struct ManifestRow {
  std::string path;
  std::string format;
  std::string defects;
  std::string tags;
  std::string family;
  std::uint64_t bytes = 0;
};

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

std::optional<std::vector<ManifestRow>> read_manifest(const fs::path& dir, std::string& error) {
  std::ifstream in(dir / "MANIFEST.tsv");
  if (!in) {
    error = fmt::format("{}: cannot open", (dir / "MANIFEST.tsv").string());
    return std::nullopt;
  }
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line, '\t');
  const auto column = [&](const char* name) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return c;
    }
    return std::nullopt;
  };
  const auto path = column("path"), format = column("format"), defects = column("defects_summary"),
             bytes = column("bytes"), tags = column("tags"), family = column("family");
  if (!path || !format || !defects || !bytes || !tags || !family) {
    error = fmt::format("{}: missing columns (path, format, defects_summary, bytes, tags, family)",
                        (dir / "MANIFEST.tsv").string());
    return std::nullopt;
  }
  std::vector<ManifestRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line, '\t');
    const auto at = [&](std::size_t c) { return c < cells.size() ? cells[c] : std::string(); };
    ManifestRow row;
    row.path = at(*path);
    row.format = at(*format);
    row.defects = at(*defects);
    row.tags = at(*tags);
    row.family = at(*family);
    row.bytes = std::strtoull(at(*bytes).c_str(), nullptr, 10);
    rows.push_back(std::move(row));
  }
  return rows;
}

/// STL, OBJ, OFF or PLY, possibly gzip-compressed, by the file name.
bool is_mesh_file(const std::string& path) {
  std::string name = fs::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (name.size() > 3 && name.ends_with(".gz")) name.resize(name.size() - 3);
  return name.ends_with(".stl") || name.ends_with(".obj") || name.ends_with(".off") ||
         name.ends_with(".ply");
}

}  // namespace

std::optional<int> collect_model_cases(const RunnerOptions& o, ModelCases& out) {
  std::vector<ModelCase>& cases = out.cases;
  for (GeneratedModel& g : degenerate_models()) {
    if (!o.write_models.empty()) {
      std::error_code ec;
      fs::create_directories(o.write_models, ec);
      if (auto ok = strata::io::write_stl(o.write_models / (g.name + ".stl"), g.soup); !ok) {
        std::fprintf(stderr, "strata-validation: %s\n", ok.error().to_string().c_str());
        return 1;
      }
    }
    auto soup = std::make_shared<strata::TriangleSoup>(std::move(g.soup));
    cases.push_back({g.name, "generated", g.defects, 0,
                     [soup]() -> strata::Result<strata::TriangleSoup> { return *soup; },
                     g.cell_mm});
  }

  std::vector<std::pair<std::string, std::uint64_t>>& too_large = out.too_large;
  std::string manifest_error;
  const auto rows = read_manifest(o.corpus, manifest_error);
  if (!rows) {
    std::fprintf(stderr, "strata-validation: %s\n", manifest_error.c_str());
    return 2;
  }
  std::vector<ManifestRow> chosen;
  for (const ManifestRow& row : *rows) {
    if (!is_mesh_file(row.path)) continue;
    if (row.bytes > o.max_bytes) {
      too_large.emplace_back(row.path, row.bytes);
      continue;
    }
    chosen.push_back(row);
  }
  if (o.quick) {
    // Small, readable files of distinct families, smallest first.
    std::sort(chosen.begin(), chosen.end(),
              [](const ManifestRow& a, const ManifestRow& b) { return a.bytes < b.bytes; });
    std::vector<ManifestRow> quick;
    std::set<std::string> families;
    for (const ManifestRow& row : chosen) {
      if (quick.size() >= kQuickCorpusFiles) break;
      if (row.bytes < 1000 || row.tags.find("empty-or-malformed") != std::string::npos) continue;
      if (!families.insert(row.family).second) continue;
      quick.push_back(row);
    }
    chosen = std::move(quick);
    too_large.clear();
  }
  std::sort(chosen.begin(), chosen.end(),
            [](const ManifestRow& a, const ManifestRow& b) { return a.path < b.path; });
  for (const ManifestRow& row : chosen) {
    const fs::path full = o.corpus / row.path;
    cases.push_back({row.path, "corpus", row.defects, row.bytes,
                     [full]() { return strata::io::read_mesh(full); }, std::nullopt});
  }

  if (!o.only.empty()) {
    std::erase_if(cases, [&](const ModelCase& c) {
      return std::none_of(o.only.begin(), o.only.end(), [&](const std::string& text) {
        return c.name.find(text) != std::string::npos;
      });
    });
  }
  return std::nullopt;
}

}  // namespace strata::validation
