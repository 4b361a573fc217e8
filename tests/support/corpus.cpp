#include "support/corpus.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <stdexcept>

namespace strata::test {
namespace {

std::vector<std::string> split(std::string_view text, std::string_view separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.emplace_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + separator.size();
  }
}

std::uint64_t parse_count(std::string_view text, const std::string& where) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size()) {
    throw std::runtime_error(where + ": expected a count, found '" + std::string(text) + "'");
  }
  return value;
}

}  // namespace

std::filesystem::path CorpusEntry::full_path() const { return corpus_dir() / path; }

bool CorpusEntry::has_tag(std::string_view tag) const {
  return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

bool CorpusEntry::is_stl() const {
  return format.starts_with("stl-") && format.find("compressed") == std::string::npos;
}

std::filesystem::path corpus_dir() { return std::filesystem::path(STRATA_SHARED_DIR) / "corpus"; }

std::vector<CorpusEntry> load_corpus_manifest() {
  const std::filesystem::path file = corpus_dir() / "MANIFEST.tsv";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open the corpus manifest " + file.string());

  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + ": empty manifest");
  std::map<std::string, std::size_t, std::less<>> column;
  const auto header = split(line, "\t");
  for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  const auto index = [&](std::string_view name) {
    const auto it = column.find(name);
    if (it == column.end()) {
      throw std::runtime_error(file.string() + ": no column '" + std::string(name) + "'");
    }
    return it->second;
  };
  const std::size_t c_path = index("path");
  const std::size_t c_format = index("format");
  const std::size_t c_facets = index("facets");
  const std::size_t c_bytes = index("bytes");
  const std::size_t c_tags = index("tags");
  const std::size_t c_defects = index("defects_summary");
  const std::size_t c_license = index("repo_license");
  const std::size_t c_family = index("family");

  std::vector<CorpusEntry> entries;
  for (std::size_t line_number = 2; std::getline(in, line); ++line_number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = file.string() + ":" + std::to_string(line_number);
    const auto fields = split(line, "\t");
    if (fields.size() != header.size()) {
      throw std::runtime_error(where + ": " + std::to_string(fields.size()) + " fields, expected " +
                               std::to_string(header.size()));
    }
    CorpusEntry e;
    e.path = fields[c_path];
    e.format = fields[c_format];
    if (!fields[c_facets].empty()) e.facets = parse_count(fields[c_facets], where);
    e.bytes = parse_count(fields[c_bytes], where);
    if (!fields[c_tags].empty()) e.tags = split(fields[c_tags], ",");
    if (!fields[c_defects].empty() && fields[c_defects] != "none") {
      e.defects = split(fields[c_defects], " | ");
    }
    e.license = fields[c_license];
    e.family = fields[c_family];
    entries.push_back(std::move(e));
  }
  return entries;
}

void PrintTo(const CorpusEntry& entry, std::ostream* os) {
  *os << entry.path.generic_string() << " (" << entry.format << ")";
}

std::string sanitize_test_name(std::string_view text) {
  if (text.empty()) return "_";
  std::string name(text);
  for (char& c : name) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!alnum) c = '_';
  }
  return name;
}

}  // namespace strata::test
