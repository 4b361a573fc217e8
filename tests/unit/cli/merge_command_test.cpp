// `strata slice --layers` and `strata merge` (SPEC §3.1b): the merge of the outputs of layer
// ranges is the output of the whole run, and a merge that cannot be right writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "strata/io/read_cells.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/corpus.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::read_file;
using test::run_cli;

constexpr const char* kAllFormats = "cells,cells-ascii,png,svg,cli,cli-binary,json";

/// A model and the coarse grid that keeps its runs quick.
struct ModelCase {
  std::string name;
  fs::path path;  ///< empty: written by make()
  std::vector<std::string> grid;
};

fs::path write_model(const fs::path& dir, const std::string& name, const TriangleSoup& soup) {
  const fs::path path = dir / (name + ".stl");
  EXPECT_TRUE(io::write_stl(path, soup, io::StlEncoding::Binary));
  return path;
}

/// Two boxes that overlap: nonzero fills the union, evenodd leaves the overlap empty.
TriangleSoup overlapping_boxes() {
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {8, 6, 5});
  const TriangleSoup second = mesh::make_box({3, 2, 2}, {11, 9, 9.5});
  soup.triangles.insert(soup.triangles.end(), second.triangles.begin(), second.triangles.end());
  return soup;
}

std::string stem_of(const fs::path& model) {
  std::string name = model.filename().string();
  return name.substr(0, name.find('.'));
}

std::vector<std::string> slice_args(const fs::path& model, const fs::path& out,
                                    const std::vector<std::string>& grid,
                                    const std::vector<std::string>& rule) {
  std::vector<std::string> args = {"slice",    model.string(), "-o", out.string(),
                                   "--format", kAllFormats,    "-q"};
  args.insert(args.end(), grid.begin(), grid.end());
  args.insert(args.end(), rule.begin(), rule.end());
  return args;
}

/// Every file under `dir`, by path relative to it.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_file(e.path());
  }
  return files;
}

bool no_files_under(const fs::path& dir) {
  if (!fs::exists(dir)) return true;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) return false;
  }
  return true;
}

/// Cut points for `parts` ranges of nz layers, uneven and with single layers among them.
std::vector<std::uint32_t> cuts_for(std::uint32_t parts, std::uint32_t nz) {
  std::vector<std::uint32_t> cuts;
  if (parts == 2) cuts = {1};
  if (parts == 3) cuts = {nz / 3, nz / 3 + 1};
  if (parts == 7) cuts = {1, 3, 4, nz / 2, nz / 2 + 1, nz - 1};
  cuts.push_back(nz);
  return cuts;
}

/// The fields of the report that merge recomputes (and those it keeps), which must be the whole
/// run's; timings, diagnostics, the job plan and threads may differ.
json comparable(const json& report) {
  json out;
  for (const char* key : {"range", "fingerprint", "formats", "grid", "cells", "metrics", "layers",
                          "open_chains", "empty_layers_inside_model", "model"}) {
    out[key] = report.at(key);
  }
  return out;
}

/// The folder a merge of `parts` ranges writes.
std::string fmt_parts(std::uint32_t parts) { return "merged" + std::to_string(parts); }

/// info's text without the line that names the file.
std::string info_without_file_line(const std::string& text) {
  return text.substr(text.find('\n') + 1);
}

struct MergeCase {
  ModelCase model;
  std::vector<std::string> rule;  ///< --fill-rule and --shell-mode
};

/// The case's model and rule, so that test listings read as names, not bytes.
void PrintTo(const MergeCase& c, std::ostream* os) {
  *os << c.model.name;
  for (const std::string& arg : c.rule) *os << ' ' << arg;
}

std::string merge_case_name(const ::testing::TestParamInfo<MergeCase>& info) {
  std::string name = info.param.model.name;
  for (std::size_t i = 1; i < info.param.rule.size(); i += 2) name += "_" + info.param.rule[i];
  return name;
}

class SliceRangesMerge : public ::testing::TestWithParam<MergeCase> {};

TEST_P(SliceRangesMerge, MergeOfRangesIsTheWholeRun) {
  const MergeCase& c = GetParam();
  test::TempDir dir("ranges");
  fs::path model = c.model.path;
  if (model.empty()) {
    model = c.model.name == "sphere" ? write_model(dir.path(), "sphere", mesh::make_sphere(6.0, 2))
                                     : write_model(dir.path(), c.model.name, overlapping_boxes());
  }
  const std::string stem = stem_of(model);
  const fs::path whole = dir / "whole";
  const auto run = run_cli(slice_args(model, whole, c.model.grid, c.rule));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json whole_report = json::parse(read_file(whole / (stem + ".json")));
  const auto nz = whole_report["grid"]["nz"].get<std::uint32_t>();
  ASSERT_GE(nz, 8u) << "the grid is too coarse for 7 uneven ranges";
  auto whole_files = files_under(whole);
  const std::string whole_report_text = whole_files.at(stem + ".json");
  whole_files.erase(stem + ".json");
  ASSERT_EQ(whole_files.count("png/" + stem + "_00000.png"), 1u);

  for (const std::uint32_t parts : {1u, 2u, 3u, 7u}) {
    SCOPED_TRACE(std::to_string(parts) + " parts");
    std::vector<std::string> merge = {"merge", "-q", "-o", (dir / fmt_parts(parts)).string()};
    std::uint32_t first = 0;
    std::vector<std::string> part_dirs;
    for (const std::uint32_t end : cuts_for(parts, nz)) {
      const fs::path part = dir / (fmt_parts(parts) + "-" + std::to_string(first));
      auto args = slice_args(model, part, c.model.grid, c.rule);
      args.push_back("--layers");
      args.push_back(end == nz && first > 0 ? std::to_string(first) + ":"
                     : end == first + 1     ? std::to_string(first)
                                            : std::to_string(first) + ":" + std::to_string(end));
      const auto sliced = run_cli(args);
      ASSERT_EQ(sliced.exit_code, 0) << sliced.err;
      // The part's cells file holds its layers: z0 is the bottom of layer `first`.
      const auto header = io::read_cells(part / (stem + ".cells"));
      ASSERT_TRUE(header);
      EXPECT_EQ(header->header.grid.nz, end - first);
      part_dirs.push_back(part.string());
      first = end;
    }
    // Parts in any order.
    std::reverse(part_dirs.begin(), part_dirs.end());
    merge.insert(merge.end(), part_dirs.begin(), part_dirs.end());
    const auto merged = run_cli(merge);
    ASSERT_EQ(merged.exit_code, 0) << merged.err;
    const fs::path out = dir / fmt_parts(parts);
    auto merged_files = files_under(out);
    const json merged_report = json::parse(merged_files.at(stem + ".json"));
    merged_files.erase(stem + ".json");
    ASSERT_EQ(merged_files.size(), whole_files.size());
    for (const auto& [name, bytes] : whole_files) {
      ASSERT_EQ(merged_files.count(name), 1u) << name;
      EXPECT_TRUE(merged_files.at(name) == bytes) << name << " differs from the whole run's";
    }
    EXPECT_EQ(comparable(merged_report), comparable(json::parse(whole_report_text)));
    EXPECT_EQ(merged_report["merged_from"].size(), cuts_for(parts, nz).size());

    if (parts == 7) {
      const auto info_whole = run_cli({"info", "--layers", (whole / (stem + ".cells")).string()});
      const auto info_merged = run_cli({"info", "--layers", (out / (stem + ".cells")).string()});
      ASSERT_EQ(info_merged.exit_code, 0) << info_merged.err;
      EXPECT_EQ(info_without_file_line(info_merged.out), info_without_file_line(info_whole.out));
    }
  }
}

std::vector<MergeCase> merge_cases() {
  const std::vector<std::string> boxes_grid = {"--cell", "0.8", "--layer", "0.6", "--shell", "1.3"};
  const std::vector<std::string> sphere_grid = {"--cell", "0.9",     "--layer",
                                                "0.7",    "--shell", "1.5"};
  std::vector<MergeCase> cases;
  for (const char* rule : {"nonzero", "evenodd"}) {
    for (const char* mode : {"distance", "layers"}) {
      const std::vector<std::string> r = {"--fill-rule", rule, "--shell-mode", mode};
      cases.push_back({{"sphere", {}, sphere_grid}, r});
      cases.push_back({{"overlapping_boxes", {}, boxes_grid}, r});
    }
  }
  cases.push_back({{"overlapping_boxes", {}, boxes_grid}, {"--fill-rule", "winding"}});
  // Corpus models, read in place: a clean part, and a soup of 18 self-intersecting shells.
  const fs::path corpus = test::corpus_dir();
  const ModelCase cura = {"cura_testModel",
                          corpus / "curaengine/tests/testModel.stl",
                          {"--cell", "1.6", "--layer", "1.7", "--shell", "2"}};
  const ModelCase spider = {"assimp_Spider_binary",
                            corpus / "assimp-testmodels/models/STL/Spider_binary.stl",
                            {"--cell", "0.45", "--layer", "0.3", "--shell", "0.5"}};
  cases.push_back({cura, {"--fill-rule", "nonzero", "--shell-mode", "distance"}});
  cases.push_back({cura, {"--fill-rule", "evenodd", "--shell-mode", "layers"}});
  cases.push_back({spider, {"--fill-rule", "nonzero", "--shell-mode", "layers"}});
  cases.push_back({spider, {"--fill-rule", "evenodd", "--shell-mode", "distance"}});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Models, SliceRangesMerge, ::testing::ValuesIn(merge_cases()),
                         merge_case_name);

// ---------------------------------------------------------------------------------------------
// Refusals: each exits 1, names what is wrong, and leaves the output folder without files.

class MergeRefusal : public ::testing::Test {
 protected:
  void SetUp() override {
    // 10 layers of 1 mm; the other model has the same grid and other bytes.
    model_ = write_model(dir_.path(), "part", mesh::make_box({0, 0, 0}, {6, 5, 10}));
    other_ = write_model(dir_.path(), "part_other", mesh::make_box({0, 0, 0}, {6, 5.5, 10}));
  }

  /// Slices layers `range` of `model` into folder `name`; returns the folder.
  fs::path slice(const std::string& name, const std::string& range,
                 std::vector<std::string> extra = {}, const fs::path& model = {}) {
    const fs::path out = dir_ / name;
    std::vector<std::string> args = {"slice",    (model.empty() ? model_ : model).string(),
                                     "-o",       out.string(),
                                     "--cell",   "1",
                                     "--layer",  "1",
                                     "--format", "cells,cells-ascii,png,json",
                                     "-q",       "--layers",
                                     range};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = run_cli(args);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return out;
  }

  /// Runs merge into a fresh folder (created empty beforehand when `existing`); expects the
  /// refusal and returns its message.
  std::string refused(const std::vector<fs::path>& parts, bool existing = false) {
    const fs::path out = dir_ / ("out" + std::to_string(++merges_));
    if (existing) fs::create_directories(out);
    std::vector<std::string> args = {"merge", "-o", out.string()};
    for (const fs::path& p : parts) args.push_back(p.string());
    const auto run = run_cli(args);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_TRUE(no_files_under(out)) << "the refused merge wrote into " << out;
    EXPECT_EQ(fs::exists(out), existing);
    return run.err;
  }

  test::TempDir dir_{"merge-refusal"};
  fs::path model_;
  fs::path other_;
  int merges_ = 0;
};

TEST_F(MergeRefusal, PartsOfAnotherModel) {
  const fs::path a = slice("a", "0:4");
  const fs::path b = slice("b", "4:", {}, other_);
  const std::string err = refused({a, b});
  EXPECT_NE(err.find(b.string()), std::string::npos) << err;
  EXPECT_NE(err.find("another model or with other options"), std::string::npos) << err;
  refused({a, b}, true);
}

TEST_F(MergeRefusal, PartsWithOtherOptions) {
  const fs::path a = slice("a", "0:4");
  const fs::path b = slice("b", "4:", {"--shell", "0.7"});
  const fs::path c = slice("c", "4:", {"--fill-rule", "evenodd"});
  EXPECT_NE(refused({a, b}).find(b.string()), std::string::npos);
  EXPECT_NE(refused({a, c}, true).find(c.string()), std::string::npos);
}

TEST_F(MergeRefusal, OverlappingParts) {
  const fs::path a = slice("a", "0:5");
  const fs::path b = slice("b", "4:");
  const std::string err = refused({b, a});
  EXPECT_NE(err.find("overlap"), std::string::npos) << err;
  EXPECT_NE(err.find(b.string()), std::string::npos) << err;
  const fs::path twice = slice("twice", "0:5");
  refused({a, twice, b}, true);
}

TEST_F(MergeRefusal, MissingLayersAreListed) {
  const fs::path a = slice("a", "0:3");
  const fs::path c = slice("c", "5:7");
  const std::string err = refused({a, c});
  // Of the 10 layers, 3..4 and 7..9 are missing.
  EXPECT_NE(err.find("layers 3..4, 7..9"), std::string::npos) << err;
  EXPECT_NE(err.find("--layers 3:5, --layers 7:10"), std::string::npos) << err;
  refused({a}, true);
}

TEST_F(MergeRefusal, IncompleteOrReportlessParts) {
  const fs::path a = slice("a", "0:4");
  const fs::path b = slice("b", "4:");
  fs::remove(b / "png" / "part_00006.png");
  const std::string err = refused({a, b});
  EXPECT_NE(err.find("part_00006.png"), std::string::npos) << err;
  fs::remove(a / "part.json");
  EXPECT_NE(refused({a, b}, true).find(a.string()), std::string::npos);
}

TEST_F(MergeRefusal, SliceRefusesARangeBeyondTheModel) {
  const auto run = run_cli({"slice", model_.string(), "-o", (dir_ / "x").string(), "--cell", "1",
                            "--layer", "1", "--layers", "8:12"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("10 layers"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  const auto page = run_cli({"slice", model_.string(), "-o", (dir_ / "y").string(), "--layers",
                             "2:3", "--format", "cells,html"});
  EXPECT_EQ(page.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "y"));
}

TEST_F(MergeRefusal, InfoShowsAPartsRange) {
  const fs::path a = slice("a", "3:6");
  const auto info = run_cli({"info", (a / "part.cells").string()});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("range    layers 3..5 of the model's 10"), std::string::npos) << info.out;
  const auto cells = io::read_cells(a / "part.cells.txt");
  ASSERT_TRUE(cells);
  EXPECT_EQ(cells->header.grid.nz, 3u);
  const json report = json::parse(read_file(a / "part.json"));
  EXPECT_EQ(report["range"], (json{{"first", 3}, {"end", 6}, {"nz_total", 10}}));
  EXPECT_EQ(cells->header.grid.z0, report["grid"]["origin_mm"][2].get<double>() + 3.0);
  EXPECT_EQ(report["layers"].size(), 3u);
  EXPECT_EQ(report["layers"][0]["k"], 3);
}

}  // namespace
}  // namespace strata
