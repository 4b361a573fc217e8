// `strata check --repair` and `strata slice --repair` as a user runs them: the repaired file, the
// untouched input, the reports, exit codes, no partial file.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

using test::read_file;

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

/// A closed box with one facet turned over and one facet repeated: needs repair.
TriangleSoup defective_box() {
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {4, 3, 2});
  auto& t = soup.triangles;
  std::swap(t[2][1], t[2][2]);
  t.push_back(t[5]);
  return soup;
}

/// A closed box with one facet missing.
TriangleSoup open_box() {
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {4, 3, 2});
  soup.triangles.erase(soup.triangles.begin() + 3);
  return soup;
}

fs::path write_model(const TempDir& tmp, const std::string& name, const TriangleSoup& soup) {
  const fs::path path = tmp / name;
  EXPECT_TRUE(io::write_stl(path, soup).has_value());
  return path;
}

TEST(CheckRepair, WritesARepairedFileThatReadsBackAndLeavesTheInputAlone) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "box.stl", defective_box());
  const std::string bytes_before = read_file(in);
  const auto run = run_cli({"check", in.string(), "--repair", (tmp / "fixed.stl").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(in), bytes_before);

  auto fixed = io::read_mesh(tmp / "fixed.stl");
  ASSERT_TRUE(fixed.has_value()) << fixed.error().to_string();
  EXPECT_EQ(fixed->format, "stl-binary");
  EXPECT_EQ(fixed->triangles, mesh::make_box({0, 0, 0}, {4, 3, 2}).triangles);
  const auto report = diagnose::diagnose_mesh(weld_vertices(*fixed), *fixed);
  EXPECT_EQ(report.verdict, diagnose::Verdict::Printable) << report.verdict_reason;

  EXPECT_NE(run.out.find("duplicate facets removed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("verdict before repair: needs-repair"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("verdict after repair:  printable"), std::string::npos) << run.out;
}

TEST(CheckRepair, ReportsTheRepairInTheJson) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "open.stl", open_box());
  const auto run = run_cli(
      {"check", in.string(), "--repair", (tmp / "fixed.stl").string(), "--fill-holes", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["verdict"], "needs-repair");
  const auto& repair = json["repair"];
  EXPECT_EQ(repair["holes"]["found"], 1);
  EXPECT_EQ(repair["holes"]["filled"], 1);
  EXPECT_EQ(repair["holes"]["facets_added"], 1);
  EXPECT_EQ(repair["output"]["facets"], 12);
  EXPECT_EQ(repair["file"], (tmp / "fixed.stl").string());
  EXPECT_EQ(repair["verdict_before"], "needs-repair");
  EXPECT_EQ(repair["verdict_after"], "printable");
  EXPECT_EQ(repair["after"]["boundary_edges"]["count"], 0);
}

TEST(CheckRepair, WithoutFillHolesTheHoleStaysOpen) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "open.stl", open_box());
  const auto run = run_cli({"check", in.string(), "--repair", (tmp / "fixed.stl").string(),
                            "--json-file", (tmp / "report.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(read_file(tmp / "report.json"));
  EXPECT_EQ(json["repair"]["holes"]["found"], 1);
  EXPECT_EQ(json["repair"]["holes"]["filled"], 0);
  EXPECT_EQ(json["repair"]["verdict_after"], "needs-repair");
  EXPECT_NE(run.out.find("--fill-holes not given"), std::string::npos) << run.out;
}

TEST(CheckRepair, RefusesToOverwriteTheModel) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "box.stl", defective_box());
  const std::string bytes_before = read_file(in);
  for (const fs::path& out : {in, tmp / "." / "box.stl"}) {
    const auto run = run_cli({"check", in.string(), "--repair", out.string()});
    EXPECT_EQ(run.exit_code, 2) << out;
    EXPECT_NE(run.err.find("overwrite"), std::string::npos) << run.err;
  }
  EXPECT_EQ(read_file(in), bytes_before);
  EXPECT_EQ(names_in(tmp.path()), std::vector<std::string>{"box.stl"});
}

TEST(CheckRepair, AnOutputItCannotWriteIsBadInputAndLeavesNoFile) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "box.stl", defective_box());
  fs::create_directory(tmp / "folder");
  for (const fs::path& out : {tmp / "missing" / "fixed.stl", tmp / "folder"}) {
    const auto run = run_cli({"check", in.string(), "--repair", out.string()});
    EXPECT_EQ(run.exit_code, 1) << out << "\n" << run.err;
    EXPECT_NE(run.err.find(out.filename().string()), std::string::npos) << run.err;
  }
  std::vector<std::string> names = names_in(tmp.path());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"box.stl", "folder"}));
  EXPECT_TRUE(fs::is_empty(tmp / "folder"));
}

TEST(CheckRepair, FillHolesWithoutRepairIsAUsageError) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "open.stl", open_box());
  EXPECT_EQ(run_cli({"check", in.string(), "--fill-holes"}).exit_code, 2);
  EXPECT_EQ(run_cli({"slice", in.string(), "-o", (tmp / "out").string(), "--fill-holes"}).exit_code,
            2);
  EXPECT_FALSE(fs::exists(tmp / "out"));
}

TEST(SliceRepair, SlicesTheRepairedMeshAndLogsTheRepair) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "open.stl", open_box());
  const std::string bytes_before = read_file(in);
  const auto run = run_cli({"slice", in.string(), "-o", (tmp / "out").string(), "--cell", "0.5",
                            "--layer", "0.5", "--format", "json", "--repair", "--fill-holes"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(in), bytes_before);
  EXPECT_NE(run.err.find("repair: 11 facets in, 12 out; 1 hole filled"), std::string::npos)
      << run.err;
  const auto json = nlohmann::json::parse(read_file(tmp / "out" / "open.json"));
  EXPECT_EQ(json["repair"]["holes"]["filled"], 1);
  EXPECT_EQ(json["repair"]["output"]["facets"], 12);
  EXPECT_EQ(json["model"]["defects"]["open_edges"], 0);
  EXPECT_EQ(json["model"]["defects"]["verdict"], "printable");
  EXPECT_EQ(json["metrics"]["mesh_volume_mm3"], 24.0);
}

TEST(SliceRepair, WithoutRepairTheReportHasNoRepairObject) {
  TempDir tmp("repair-cli");
  const fs::path in = write_model(tmp, "open.stl", open_box());
  const auto run = run_cli({"slice", in.string(), "-o", (tmp / "out").string(), "--cell", "0.5",
                            "--layer", "0.5", "--format", "json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(read_file(tmp / "out" / "open.json"));
  EXPECT_FALSE(json.contains("repair"));
  EXPECT_EQ(json["model"]["defects"]["open_edges"], 3);
}

}  // namespace
}  // namespace strata
