#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace strata::test {

/// One row of the shared corpus manifest (`<repo>/../shared/corpus/MANIFEST.tsv`).
struct CorpusEntry {
  std::filesystem::path path;           ///< relative to corpus_dir(), as in the manifest
  std::string format;                   ///< e.g. "stl-binary", "off [non-STL: needs conversion]"
  std::optional<std::uint64_t> facets;  ///< empty when the manifest leaves it blank
  std::uint64_t bytes = 0;              ///< file size
  std::vector<std::string> tags;        ///< e.g. "clean", "open", "non-manifold", "large"
  std::vector<std::string> defects;     ///< defects_summary split at " | "; empty for "none"
  std::string license;                  ///< repo_license
  std::string family;                   ///< models that are versions of one another share it

  /// The file itself: corpus_dir() / path.
  std::filesystem::path full_path() const;
  bool has_tag(std::string_view tag) const;
  /// True for the STL formats ("stl-ascii", "stl-binary", ...), false for OBJ/OFF/PLY/... and
  /// compressed files.
  bool is_stl() const;
};

/// The shared corpus folder: STRATA_SHARED_DIR "/corpus".
std::filesystem::path corpus_dir();

/// Parses MANIFEST.tsv (columns found by their header names, so their order may change).
/// Throws std::runtime_error naming the file and line when it is missing or malformed: a corpus
/// test must fail loudly, not pass with zero cases.
std::vector<CorpusEntry> load_corpus_manifest();

/// A GoogleTest parameter name for any text: every character outside [A-Za-z0-9] becomes '_'
/// ("numpy-stl/tests/Moon.stl" -> "numpy_stl_tests_Moon_stl"); empty text gives "_".
std::string sanitize_test_name(std::string_view text);

/// Lets GoogleTest print a CorpusEntry parameter as its path (instead of a byte dump).
void PrintTo(const CorpusEntry& entry, std::ostream* os);

/// Name generator for INSTANTIATE_TEST_SUITE_P over CorpusEntry values: the sanitised path, so
/// `--gtest_filter='*rear_case*'` selects a model.
///
///     INSTANTIATE_TEST_SUITE_P(Corpus, ReadsEveryMesh,
///                              testing::ValuesIn(load_corpus_manifest()), CorpusTestName{});
struct CorpusTestName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& info) const {
    return sanitize_test_name(info.param.path.generic_string());
  }
};

}  // namespace strata::test
