// `strata plan`: ranges for a scheduler that tile the layers, balanced by facet crossings, and
// that `slice --layers` and `merge` take as they are.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::run_cli;

/// A plain block with a many-sided cylinder on top: nearly all crossings are in the cylinder.
fs::path write_block_and_tower(const fs::path& dir) {
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {20, 20, 20});
  const TriangleSoup tower = mesh::translate_soup(mesh::make_cylinder(4.0, 4.0, 600), {10, 10, 20});
  soup.triangles.insert(soup.triangles.end(), tower.triangles.begin(), tower.triangles.end());
  const fs::path path = dir / "tower.stl";
  EXPECT_TRUE(io::write_stl(path, soup, io::StlEncoding::Binary));
  return path;
}

/// "A:B" of a planned part.
std::string fmt_range(const json& part) {
  return std::to_string(part["first"].get<std::uint32_t>()) + ":" +
         std::to_string(part["end"].get<std::uint32_t>());
}

TEST(PlanCommand, JsonRangesTileTheLayersByWorkNotByCount) {
  test::TempDir dir("plan");
  const fs::path model = write_block_and_tower(dir.path());
  const auto run =
      run_cli({"plan", model.string(), "--parts", "3", "--cell", "2", "--layer", "0.5", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json plan = json::parse(run.out);
  ASSERT_EQ(plan["nz_total"], 48);
  ASSERT_EQ(plan["parts"].size(), 3u);
  std::uint32_t next = 0;
  for (const json& part : plan["parts"]) {
    EXPECT_EQ(part["first"], next);
    EXPECT_GT(part["end"].get<std::uint32_t>(), next);
    EXPECT_EQ(part["layers"], fmt_range(part));
    next = part["end"].get<std::uint32_t>();
  }
  EXPECT_EQ(next, 48u);
  // Equal counts would be 16 layers a part; the block's 40 layers weigh less than the tower's 8.
  EXPECT_GT(plan["parts"][0]["end"].get<std::uint32_t>(), 40u);
}

TEST(PlanCommand, PlannedRangesSliceAndMergeIntoTheWholeRun) {
  test::TempDir dir("plan-merge");
  const fs::path model = write_block_and_tower(dir.path());
  const std::vector<std::string> grid = {"--cell", "2", "--layer", "0.5", "--shell", "1"};
  auto args = std::vector<std::string>{"plan", model.string(), "--parts", "4", "--json"};
  args.insert(args.end(), grid.begin(), grid.end());
  const auto planned = run_cli(args);
  ASSERT_EQ(planned.exit_code, 0) << planned.err;
  std::vector<std::string> merge = {"merge", "-q", "-o", (dir / "merged").string()};
  const json plan = json::parse(planned.out);
  for (const json& part : plan["parts"]) {
    const fs::path out = dir / ("part" + part["part"].dump());
    std::vector<std::string> slice = {"slice",
                                      model.string(),
                                      "-o",
                                      out.string(),
                                      "-q",
                                      "--layers",
                                      part["layers"].get<std::string>()};
    slice.insert(slice.end(), grid.begin(), grid.end());
    const auto sliced = run_cli(slice);
    ASSERT_EQ(sliced.exit_code, 0) << sliced.err;
    merge.push_back(out.string());
  }
  ASSERT_EQ(run_cli(merge).exit_code, 0);
  std::vector<std::string> whole = {
      "slice", model.string(), "-o", (dir / "whole").string(), "-q", "--format", "cells,png,json"};
  whole.insert(whole.end(), grid.begin(), grid.end());
  ASSERT_EQ(run_cli(whole).exit_code, 0);
  EXPECT_TRUE(test::read_file(dir / "merged" / "tower.cells") ==
              test::read_file(dir / "whole" / "tower.cells"));
}

TEST(PlanCommand, TableAndUsageErrors) {
  test::TempDir dir("plan-table");
  const fs::path model = write_block_and_tower(dir.path());
  const auto table =
      run_cli({"plan", model.string(), "--parts", "2", "--cell", "2", "--layer", "0.5"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("part      layers"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find(":48"), std::string::npos) << table.out;
  const auto too_many =
      run_cli({"plan", model.string(), "--parts", "49", "--cell", "2", "--layer", "0.5"});
  EXPECT_EQ(too_many.exit_code, 2);
  EXPECT_NE(too_many.err.find("48 layers"), std::string::npos) << too_many.err;
  EXPECT_EQ(run_cli({"plan", model.string(), "--parts", "0"}).exit_code, 2);
  const auto missing = run_cli({"plan", (dir / "none.stl").string(), "--parts", "2"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("none.stl"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace strata
