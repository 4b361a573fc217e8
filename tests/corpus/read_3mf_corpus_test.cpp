// Every 3MF file of the shared corpus through read_mesh: it loads (a sound soup in millimetres,
// each build item placed) or fails with Error{BadInput} naming the file and saying what is wrong;
// never a crash, an exception, or an empty soup.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "support/corpus.hpp"

namespace strata::io {
namespace {

using test::CorpusEntry;

std::vector<CorpusEntry> three_mf_files() {
  std::vector<CorpusEntry> out;
  for (auto& e : test::load_corpus_manifest()) {
    if (e.format.starts_with("3mf")) out.push_back(std::move(e));
  }
  return out;
}

class Read3mfCorpus : public ::testing::TestWithParam<CorpusEntry> {};

TEST_P(Read3mfCorpus, LoadsOrGivesAClearError) {
  const CorpusEntry& e = GetParam();
  std::optional<Result<TriangleSoup>> read;
  try {
    read = read_mesh(e.full_path());
  } catch (const std::exception& ex) {
    FAIL() << e.path << ": read_mesh threw " << ex.what();
  }
  ASSERT_TRUE(read.has_value());
  if (!*read) {
    const Error& error = read->error();
    EXPECT_EQ(error.code, ErrorCode::BadInput);
    EXPECT_TRUE(error.location.starts_with(e.full_path().string())) << error.location;
    EXPECT_FALSE(error.message.empty());
    std::printf("%s: refused: %s\n", e.path.generic_string().c_str(), error.message.c_str());
    return;
  }
  const TriangleSoup& soup = read->value();
  EXPECT_EQ(soup.format, "3mf");
  ASSERT_FALSE(soup.triangles.empty());
  for (const auto& t : soup.triangles) {
    for (const Vec3& p : t) {
      ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << e.path;
    }
  }
  for (const Diagnostic& d : soup.diagnostics) {
    EXPECT_FALSE(d.code.empty());
    EXPECT_TRUE(d.message.starts_with(e.full_path().string())) << d.message;
  }
  // Each mesh object is placed at least once: never fewer triangles than the manifest's count of
  // the objects' own triangles, more where components repeat an object.
  if (e.facets) {
    EXPECT_GE(soup.triangles.size(), *e.facets) << e.path;
  }
  std::printf("%s: %zu triangles\n", e.path.generic_string().c_str(), soup.triangles.size());
}

INSTANTIATE_TEST_SUITE_P(Corpus, Read3mfCorpus, ::testing::ValuesIn(three_mf_files()),
                         test::CorpusTestName{});

TEST(Read3mfCorpusManifest, ListsThe3mfFiles) {
  // A manifest without 3MF files would turn the suite above into no test at all.
  EXPECT_GE(three_mf_files().size(), 5u);
}

}  // namespace
}  // namespace strata::io
