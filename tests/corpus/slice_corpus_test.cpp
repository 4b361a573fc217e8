// Every mesh of ../shared/corpus either slices without a crash or is refused with a clear
// message. Files over 5 MB are skipped here (say so) to keep CI within its time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/corpus.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
constexpr std::uint64_t kMaxBytes = 5'000'000;

bool is_mesh_format(const test::CorpusEntry& e) {
  const std::string& f = e.format;
  return f.rfind("stl", 0) == 0 || f.rfind("obj", 0) == 0 || f.rfind("off", 0) == 0 ||
         f.rfind("ply", 0) == 0 || f.rfind("3mf", 0) == 0;
}

std::vector<test::CorpusEntry> meshes() {
  std::vector<test::CorpusEntry> out;
  for (auto& e : test::load_corpus_manifest()) {
    if (is_mesh_format(e)) out.push_back(e);
  }
  return out;
}

class CounterSink final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    ++layers;
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}
  std::uint32_t layers = 0;
};

class SliceCorpus : public ::testing::TestWithParam<test::CorpusEntry> {};

TEST_P(SliceCorpus, SlicesOrRefusesClearly) {
  const test::CorpusEntry& entry = GetParam();
  if (entry.bytes > kMaxBytes) {
    GTEST_SKIP() << entry.path << ": " << entry.bytes / 1000000.0
                 << " MB, over the 5 MB limit of the CI corpus walk";
  }
  auto soup = io::read_mesh(entry.full_path());
  if (!soup) {
    EXPECT_FALSE(soup.error().message.empty());
    EXPECT_NE(soup.error().to_string().find(entry.full_path().filename().string()),
              std::string::npos)
        << soup.error().to_string();
    return;
  }
  const IndexedMesh mesh = weld_vertices(*soup);
  const Bbox3 box = mesh.bounds();
  // About 48 cells along the longest side, at least one layer: a real slice of every model.
  const double extent =
      std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
  SliceOptions options;
  const double cell = extent > 0 ? extent / 48.0 : 1.0;
  options.grid = GridOptions{cell, cell, cell, std::nullopt};
  options.shell_mm = 2.0 * cell;
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    options.fill_rule = rule;
    auto grid = make_grid(box, options.grid);
    ASSERT_TRUE(grid.has_value()) << grid.error().to_string();
    CounterSink sink;
    LayerSink* sinks[] = {&sink};
    auto summary = slice_model(mesh, *grid, options, sinks);
    ASSERT_TRUE(summary.has_value()) << summary.error().to_string();
    EXPECT_EQ(sink.layers, grid->nz);
    EXPECT_EQ(summary->class_counts[0] + summary->class_counts[1] + summary->class_counts[2],
              grid->cell_count());
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, SliceCorpus, ::testing::ValuesIn(meshes()),
                         test::CorpusTestName{});

std::vector<test::CorpusEntry> malformed() {
  std::vector<test::CorpusEntry> out;
  for (auto& e : test::load_corpus_manifest()) {
    if (e.has_tag("empty-or-malformed")) out.push_back(e);
  }
  return out;
}

class MalformedCorpus : public ::testing::TestWithParam<test::CorpusEntry> {};

TEST_P(MalformedCorpus, CommandLineExitsOneOrSlicesAndLeavesNoPartialOutput) {
  const test::CorpusEntry& entry = GetParam();
  test::TempDir tmp("malformed");
  const auto run = test::run_cli({"slice", entry.full_path().string(), "-o", (tmp / "out").string(),
                                  "--cell", "1000", "--layer", "1000", "--format", "cells,json"});
  ASSERT_FALSE(run.timed_out);
  ASSERT_EQ(run.term_signal, 0) << run.err;
  if (run.exit_code == 0) {
    // Readable after all (odd but valid): both outputs complete.
    EXPECT_TRUE(fs::exists(tmp / "out"));
    return;
  }
  EXPECT_TRUE(run.exit_code == 1 || run.exit_code == 2) << run.exit_code << " " << run.err;
  EXPECT_NE(run.err.find(entry.full_path().filename().string()), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(tmp / "out")) << "partial output left behind";
}

INSTANTIATE_TEST_SUITE_P(Corpus, MalformedCorpus, ::testing::ValuesIn(malformed()),
                         test::CorpusTestName{});

}  // namespace
}  // namespace strata
