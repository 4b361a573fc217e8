// Knowing the job before starting it: the plan (cells, output sizes, time) recorded in the
// report, the refusal of outputs that cannot fit the free space before anything is written, the
// warning naming --units for a model of an implausible size, and grid errors naming the model.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_cli;

const std::string kTetrahedron = std::string(STRATA_DATA_DIR) + "/tetrahedron.stl";

std::uintmax_t bytes_under(const fs::path& dir) {
  std::uintmax_t total = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) total += e.file_size();
  }
  return total;
}

TEST(JobPlan, ReportRecordsThePlanAndItsSizesHold) {
  const test::TempDir tmp("plan");
  const auto run =
      run_cli({"slice", kTetrahedron, "-o", (tmp / "out").string(), "--cell", "0.2", "--layer",
               "0.25", "--format", "cells,cells-ascii,png,svg,cli,cli-binary,json", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(read_file(tmp / "out" / "tetrahedron.json"));
  const auto& plan = report["plan"];
  // 10 mm / 0.2 mm = 50 columns and rows, 10 mm / 0.25 mm = 40 layers.
  EXPECT_EQ(plan["cells"].get<double>(), 50.0 * 50.0 * 40.0);
  const auto& outputs = plan["outputs"];
  ASSERT_EQ(outputs.size(), 7u);
  // The cells file's size is exact: 80 + 40 layers of ceil(2500 / 4) bytes.
  EXPECT_EQ(outputs["cells"]["exact"], true);
  EXPECT_EQ(outputs["cells"]["bytes"].get<double>(), 80.0 + 40.0 * 625.0);
  EXPECT_EQ(fs::file_size(tmp / "out" / "tetrahedron.cells"), 80u + 40u * 625u);
  // The others are lower bounds of what was written.
  EXPECT_EQ(outputs["cells-ascii"]["exact"], false);
  EXPECT_LE(outputs["cells-ascii"]["bytes"].get<double>(),
            static_cast<double>(fs::file_size(tmp / "out" / "tetrahedron.cells.txt")));
  EXPECT_LE(outputs["png"]["bytes"].get<double>(),
            static_cast<double>(bytes_under(tmp / "out" / "png")));
  EXPECT_LE(outputs["svg"]["bytes"].get<double>(),
            static_cast<double>(bytes_under(tmp / "out" / "svg")));
  EXPECT_LE(outputs["cli"]["bytes"].get<double>(),
            static_cast<double>(fs::file_size(tmp / "out" / "tetrahedron.cli")));
  EXPECT_LE(outputs["cli-binary"]["bytes"].get<double>(),
            static_cast<double>(fs::file_size(tmp / "out" / "tetrahedron.bin.cli")));
  EXPECT_LE(outputs["json"]["bytes"].get<double>(),
            static_cast<double>(fs::file_size(tmp / "out" / "tetrahedron.json")));
  EXPECT_GT(plan["seconds_estimate"].get<double>(), 0.0);
}

TEST(JobPlan, HtmlPageLowerBoundHolds) {
  const test::TempDir tmp("plan");
  const auto run = run_cli({"slice", kTetrahedron, "-o", (tmp / "out").string(), "--cell", "0.5",
                            "--layer", "0.5", "--format", "html,json", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(read_file(tmp / "out" / "tetrahedron.json"));
  EXPECT_LE(report["plan"]["outputs"]["html"]["bytes"].get<double>(),
            static_cast<double>(fs::file_size(tmp / "out" / "tetrahedron.html")));
}

TEST(JobPlan, OutputsLargerThanTheFreeSpaceFailBeforeAnythingIsWritten) {
  // 10^4 x 10^4 cells a layer, 10^7 layers: a cells file of 2.5 * 10^14 bytes (250 TB).
  const test::TempDir tmp("plan");
  const fs::path out = tmp / "out";
  test::CliRunOptions quick;
  quick.timeout = std::chrono::seconds(60);
  const auto run = run_cli({"slice", kTetrahedron, "-o", out.string(), "--cell", "0.001", "--layer",
                            "0.000001", "--format", "cells"},
                           {}, quick);
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const std::string expected_start =
      "strata: " + out.string() +
      ": the outputs need at least 250.0 TB (cells 250.0 TB), but the file system has ";
  EXPECT_EQ(run.err.rfind(expected_start, 0), 0u) << run.err;
  EXPECT_NE(run.err.find(" free; nothing was written\n"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(JobPlan, ModelBeyondAnyBuildBoxGetsAWarningNamingUnits) {
  // A triangle 3 m long, as a building-scale file in millimetres would be.
  const test::TempDir tmp("plan");
  const fs::path obj =
      test::write_text_file(tmp / "hall.obj", "v 0 0 0\nv 3000 0 0\nv 0 1000 500\nf 1 2 3\n");
  const std::string warning =
      "warning: the model is 3000 x 1000 x 500 mm, larger than any printer's build box: if its "
      "file is not in millimetres, give its unit with --units (cm, m, in, um) or a factor with "
      "--scale";
  const auto run = run_cli({"slice", obj.string(), "-o", (tmp / "out").string(), "--cell", "100",
                            "--layer", "100", "--format", "cells", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("strata: " + warning + "\n"), std::string::npos) << run.err;
  const auto check = run_cli({"check", obj.string()});
  EXPECT_NE(check.out.find("size     3000 x 1000 x 500 mm\n"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find(warning.substr(0, 7) + "  " + warning.substr(9) + "\n"),
            std::string::npos)
      << check.out;
  // Read in metres' thousandths, the same file is a plausible 3 x 1 x 0.5 mm part.
  const auto scaled = run_cli({"check", obj.string(), "--scale", "0.001"});
  EXPECT_EQ(scaled.out.find("larger than any printer's build box"), std::string::npos)
      << scaled.out;
}

TEST(JobPlan, ModelInsideOneCellGetsAWarningNamingUnits) {
  // 8 x 4 x 2 micrometres: a part in metres read as millimetres.
  const test::TempDir tmp("plan");
  const fs::path obj =
      test::write_text_file(tmp / "tiny.obj", "v 0 0 0\nv 0.008 0 0\nv 0 0.004 0.002\nf 1 2 3\n");
  const auto run =
      run_cli({"slice", obj.string(), "-o", (tmp / "out").string(), "--format", "cells", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("strata: warning: the model is 0.008 x 0.004 x 0.002 mm, smaller than "
                         "one cell (0.1 x 0.1 x 0.1 mm): if its file is not in millimetres, "
                         "give its unit with --units (cm, m, in) or a factor with --scale\n"),
            std::string::npos)
      << run.err;
  const auto metres = run_cli({"slice", obj.string(), "-o", (tmp / "m").string(), "--units", "m",
                               "--format", "cells", "-q"});
  ASSERT_EQ(metres.exit_code, 0) << metres.err;
  EXPECT_EQ(metres.err.find("warning: the model is"), std::string::npos) << metres.err;
}

TEST(JobPlan, CheckPrintsWhatASliceAtTheDefaultsWouldMake) {
  const auto check = run_cli({"check", kTetrahedron});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.out.find("size     10 x 10 x 10 mm\n"), std::string::npos) << check.out;
  // 100 x 100 x 100 cells at 0.1 mm; the cells file 80 + 100 * 2500 bytes.
  EXPECT_NE(check.out.find("slice    at the defaults: 1,000,000 cells; cells 250.1 kB, png >= "),
            std::string::npos)
      << check.out;
}

TEST(JobPlan, GridTooLargeForTheModelNamesTheFile) {
  const auto run = run_cli({"slice", kTetrahedron, "--cell", "1e-9", "--format", "cells"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("strata: " + kTetrahedron + ": the model spans 10 mm along x: ", 0), 0u)
      << run.err;
  EXPECT_NE(run.err.find("use larger cells"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace strata
