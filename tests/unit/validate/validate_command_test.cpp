// `strata validate`, run as a process (the command lives in src/cli/validate_command.cpp).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

using test::run_cli;
using test::TempDir;

std::string write_box(const TempDir& dir) {
  const auto path = dir / "box.stl";
  EXPECT_TRUE(io::write_stl(path, mesh::make_box({0, 0, 0}, {6.5, 4.5, 3.5})).has_value());
  return path.string();
}

TEST(ValidateCommand, ExitsZeroAndSaysSoWhenTheCellsAgree) {
  TempDir dir("validate");
  const auto run = run_cli({"validate", write_box(dir), "--cell", "0.5", "--layer", "0.5"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("AGREE"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("exact/fast"), std::string::npos) << run.out;
}

TEST(ValidateCommand, WritesTheJsonReport) {
  TempDir dir("validate");
  const auto json_path = dir / "box-validation.json";
  const auto run = run_cli({"validate", write_box(dir), "--cell", "0.5", "--layer", "0.5",
                            "--scan-offset", "0.0001", "--json", json_path.string(), "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  std::ifstream in(json_path);
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report.at("verdict"), "agree");
  EXPECT_EQ(report.at("grid").at("nz"), 7);
  EXPECT_TRUE(report.at("scan_offset").at("measured").get<bool>());
}

TEST(ValidateCommand, PrintsTheReferenceSlicer) {
  TempDir dir("validate");
  const auto run = run_cli({"validate", write_box(dir), "--cell", "0.5", "--layer", "0.5"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("reference slicer (CGAL Polygon_mesh_slicer"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("exact kernel): 7 layers"), std::string::npos) << run.out;
}

TEST(ValidateCommand, TurnsTheReferenceSlicerOff) {
  TempDir dir("validate");
  const auto json_path = dir / "box-validation.json";
  const auto run = run_cli({"validate", write_box(dir), "--cell", "0.5", "--layer", "0.5",
                            "--reference-slicer", "off", "--json", json_path.string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("exact kernel): off"), std::string::npos) << run.out;
  std::ifstream in(json_path);
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_FALSE(report.at("reference_slicer").at("ran").get<bool>());
  EXPECT_EQ(report.at("reference_slicer").at("skipped"), "off");
}

TEST(ValidateCommand, RefusesAnUnknownReferenceSlicerValue) {
  TempDir dir("validate");
  const auto run = run_cli({"validate", write_box(dir), "--reference-slicer", "maybe"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

TEST(ValidateCommand, RefusesTheWindingRuleAsBadUsage) {
  TempDir dir("validate");
  const auto run = run_cli({"validate", write_box(dir), "--fill-rule", "winding"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("winding"), std::string::npos) << run.err;
}

TEST(ValidateCommand, NamesAMissingModelAsBadInput) {
  TempDir dir("validate");
  const auto run = run_cli({"validate", (dir / "missing.stl").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("missing.stl"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace strata
