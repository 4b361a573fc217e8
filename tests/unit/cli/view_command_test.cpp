// `strata view` and `strata slice --format html` as a user runs them: one page, its data the
// cells of the run, every error path leaving no page behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "strata/io/cells_format.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/page_encodings.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::run_cli;
using test::TempDir;

const std::string kRing = std::string(STRATA_DATA_DIR) + "/ring.stl";

using test::base64_decode;
using test::inflate;
using test::read_file;

/// The data a page holds, parsed; fails the test when the page has none.
json page_data(const fs::path& page) {
  const std::string html = read_file(page);
  const std::string open = R"(<script id="strata-data" type="application/json">)";
  const std::size_t at = html.find(open);
  EXPECT_NE(at, std::string::npos) << page;
  if (at == std::string::npos) return json();
  const std::size_t begin = at + open.size();
  const std::size_t end = html.find("</script>", begin);
  EXPECT_NE(end, std::string::npos);
  EXPECT_EQ(html.find("__STRATA_VIEW_DATA__"), std::string::npos) << "the marker is replaced";
  return json::parse(html.substr(begin, end - begin));
}

TEST(ViewCommand, WritesOnePageForAModelAndSaysHowToOpenIt) {
  TempDir tmp("view");
  const auto run = run_cli(
      {"view", kRing, "-o", (tmp / "ring.html").string(), "--cell", "0.5", "--layer", "0.5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("file://"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("ring.html"), std::string::npos);
  ASSERT_TRUE(fs::exists(tmp / "ring.html"));
  EXPECT_FALSE(fs::exists(tmp / "ring-strata")) << "view writes the page only";
  const json data = page_data(tmp / "ring.html");
  EXPECT_EQ(data["format"], "strata-view");
  EXPECT_EQ(data["title"], "ring");
  const std::uint32_t nz = data["grid"]["nz"];
  EXPECT_EQ(data["layers"]["stored"].size(), nz);
  EXPECT_EQ(data["layers"]["cells"].size(), nz);
  EXPECT_EQ(data["layers"]["stride"], 1);
  EXPECT_EQ(data["report"]["grid"]["nz"], nz);
  EXPECT_FALSE(data["mesh"]["simplified"].get<bool>());
  EXPECT_EQ(data["mesh"]["facets_shown"], data["mesh"]["facets_in_model"]);
  EXPECT_EQ(data["check"]["verdict"], "printable");
  EXPECT_TRUE(data["check"]["self_intersections_checked"].get<bool>());
  // The ring has one outer loop and one hole in every layer.
  for (const json& layer : data["layers"]["contours"]) {
    ASSERT_EQ(layer.size(), 2u);
    std::set<std::string> kinds = {layer[0]["kind"], layer[1]["kind"]};
    EXPECT_EQ(kinds, (std::set<std::string>{"outer", "hole"}));
  }
}

TEST(ViewCommand, PageCellsAreTheCellsFileByteForByte) {
  TempDir tmp("view");
  const auto run = run_cli({"slice", kRing, "-o", (tmp / "out").string(), "--cell", "0.4",
                            "--layer", "0.3", "--format", "cells,html", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string cells = read_file(tmp / "out" / "ring.cells");
  const json data = page_data(tmp / "out" / "ring.html");
  GridSpec g;
  g.nx = data["grid"]["nx"];
  g.ny = data["grid"]["ny"];
  g.nz = data["grid"]["nz"];
  const std::uint64_t layer_bytes = io::packed_layer_bytes(g);
  ASSERT_EQ(cells.size(), io::binary_cells_file_bytes(g));
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    const std::string packed = base64_decode(data["layers"]["cells"][k].get<std::string>());
    EXPECT_EQ(inflate(packed, layer_bytes), cells.substr(80 + k * layer_bytes, layer_bytes))
        << "layer " << k;
  }
}

TEST(ViewCommand, HtmlIsADefaultFormatOfSlice) {
  TempDir tmp("view");
  const auto run = run_cli({"slice", std::string(STRATA_DATA_DIR) + "/tetrahedron.stl", "-o",
                            (tmp / "out").string(), "--cell", "0.5", "--layer", "0.5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(tmp / "out" / "tetrahedron.html"));
  EXPECT_NE(run.out.find("page    "), std::string::npos) << run.out;
  const json data = page_data(tmp / "out" / "tetrahedron.html");
  EXPECT_FALSE(data["check"]["self_intersections_checked"].get<bool>());
  EXPECT_NE(data["notes"].dump().find("self-intersections not checked"), std::string::npos);
}

TEST(ViewCommand, FromAnOutputFolderShowsItsCellsWithTheModelsContours) {
  TempDir tmp("view");
  fs::copy_file(kRing, tmp / "ring.stl");
  ASSERT_EQ(run_cli({"slice", (tmp / "ring.stl").string(), "-o", (tmp / "out").string(), "--cell",
                     "0.5", "--layer", "0.5", "--format", "cells,json", "-q"})
                .exit_code,
            0);
  const auto run = run_cli({"view", (tmp / "out").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json data = page_data(tmp / "out" / "ring.html");
  EXPECT_EQ(data["source"]["kind"], "folder");
  EXPECT_FALSE(data["mesh"].is_null());
  EXPECT_EQ(data["layers"]["contours"][0].size(), 2u);
  EXPECT_EQ(data["notes"].size(), 0u) << data["notes"].dump();

  // Without the model, the cells file alone, and the page says so.
  fs::remove(tmp / "ring.stl");
  fs::remove(tmp / "out" / "ring.html");
  const auto alone = run_cli({"view", (tmp / "out").string(), "-o", (tmp / "alone.html").string()});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const json cells_only = page_data(tmp / "alone.html");
  EXPECT_TRUE(cells_only["mesh"].is_null());
  EXPECT_NE(cells_only["notes"].dump().find("model not found"), std::string::npos);
  EXPECT_EQ(cells_only["layers"]["cells"], data["layers"]["cells"]);
}

TEST(ViewCommand, AValidationReportInTheFolderIsShown) {
  TempDir tmp("view");
  ASSERT_EQ(run_cli({"slice", kRing, "-o", (tmp / "out").string(), "--cell", "0.5", "--layer",
                     "0.5", "--format", "cells,json", "-q"})
                .exit_code,
            0);
  const auto validate = run_cli({"validate", kRing, "--cell", "0.5", "--layer", "0.5", "--json",
                                 (tmp / "out" / "ring.validation.json").string(), "-q"});
  ASSERT_EQ(validate.exit_code, 0) << validate.err;
  const auto run = run_cli({"view", (tmp / "out").string(), "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const json data = page_data(tmp / "out" / "ring.html");
  ASSERT_FALSE(data["validation"].is_null());
  EXPECT_GT(data["validation"]["cells_compared"].get<std::uint64_t>(), 0u);
  EXPECT_EQ(data["validation"]["cells_differing"], 0);
}

TEST(ViewCommand, ABudgetTooSmallForEveryLayerKeepsEveryNthAndSaysSo) {
  TempDir tmp("view");
  const auto run = run_cli({"view", kRing, "-o", (tmp / "ring.html").string(), "--cell", "0.25",
                            "--layer", "0.25", "--page-budget", "0.02", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json data = page_data(tmp / "ring.html");
  const std::uint32_t stride = data["layers"]["stride"];
  EXPECT_GT(stride, 1u);
  EXPECT_LT(data["layers"]["stored"].size(), data["grid"]["nz"].get<std::size_t>());
  EXPECT_TRUE(data["layers"]["hatches"].is_null());
  EXPECT_NE(data["notes"].dump().find("subsampled stack"), std::string::npos);
}

TEST(ViewCommand, ALargeMeshIsSimplifiedForDisplayOnly) {
  TempDir tmp("view");
  ASSERT_TRUE(io::write_stl(tmp / "sphere.stl", mesh::make_sphere(5.0, 4), io::StlEncoding::Binary)
                  .has_value());
  const auto run =
      run_cli({"view", (tmp / "sphere.stl").string(), "-o", (tmp / "sphere.html").string(),
               "--cell", "0.5", "--layer", "0.5", "--page-facets", "1000", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json data = page_data(tmp / "sphere.html");
  EXPECT_TRUE(data["mesh"]["simplified"].get<bool>());
  EXPECT_EQ(data["mesh"]["facets_in_model"], 5120);
  EXPECT_LE(data["mesh"]["facets_shown"].get<std::size_t>(), 1100u);
  EXPECT_GE(data["mesh"]["facets_shown"].get<std::size_t>(), 500u);
  EXPECT_NE(data["notes"].dump().find("simplified from 5,120 to"), std::string::npos);
}

TEST(ViewCommand, NamesInThePageCannotEndItsScript) {
  TempDir tmp("view");
  fs::create_directories(tmp / "a<" / "script>");
  fs::copy_file(std::string(STRATA_DATA_DIR) + "/tetrahedron.stl",
                tmp / "a<" / "script>" / "t.stl");
  const auto run = run_cli({"view", (tmp / "a<" / "script>" / "t.stl").string(), "-o",
                            (tmp / "t.html").string(), "--cell", "1", "--layer", "1", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json data = page_data(tmp / "t.html");
  EXPECT_NE(data["source"]["path"].get<std::string>().find("a</script>"), std::string::npos);
}

TEST(ViewCommand, BadInputWritesNoPage) {
  TempDir tmp("view");
  const auto bad =
      run_cli({"view", std::string(STRATA_DATA_DIR) + "/adversarial/truncated_binary.stl", "-o",
               (tmp / "bad.html").string()});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("truncated_binary.stl"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(tmp / "bad.html"));

  fs::create_directories(tmp / "empty");
  const auto empty = run_cli({"view", (tmp / "empty").string()});
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.err.find("no cells file"), std::string::npos) << empty.err;
  EXPECT_TRUE(fs::is_empty(tmp / "empty"));

  const auto missing = run_cli({"view", (tmp / "nothing.stl").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("nothing.stl"), std::string::npos) << missing.err;

  const auto usage = run_cli({"view", kRing, "--page-budget", "-3"});
  EXPECT_EQ(usage.exit_code, 2);
  for (const auto& e : fs::directory_iterator(tmp.path())) {
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  }
}

TEST(InfoCommand, NamesTheClassOfOneCell) {
  TempDir tmp("view");
  ASSERT_EQ(run_cli({"slice", kRing, "-o", (tmp / "out").string(), "--cell", "0.5", "--layer",
                     "0.5", "--format", "cells", "-q"})
                .exit_code,
            0);
  const std::string file = (tmp / "out" / "ring.cells").string();
  const auto corner = run_cli({"info", file, "--cell", "0,0,0"});
  ASSERT_EQ(corner.exit_code, 0) << corner.err;
  EXPECT_EQ(corner.out.rfind("cell 0,0,0 empty (00)", 0), 0u) << corner.out;
  const auto outside = run_cli({"info", file, "--cell", "0,0,100000"});
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("outside the grid"), std::string::npos) << outside.err;
}

}  // namespace
}  // namespace strata
