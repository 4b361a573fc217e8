// `strata slice --format cli,svg` does only the work those formats need, and writes the same
// contour files as a run that classifies every cell.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_cli;
using test::TempDir;

TEST(ContourOnlyCommand, WritesTheSameContourFilesAndSaysTheCellsWereNotClassified) {
  TempDir tmp("contour-only");
  const std::string ring = std::string(STRATA_DATA_DIR) + "/ring.stl";
  const auto lean = run_cli({"slice", ring, "-o", (tmp / "lean").string(), "--format",
                             "cli,cli-binary,svg", "--cell", "0.25", "--layer", "0.25"});
  ASSERT_EQ(lean.exit_code, 0) << lean.err;
  const auto full = run_cli({"slice", ring, "-o", (tmp / "full").string(), "--format",
                             "cli,cli-binary,svg,cells,json", "--cell", "0.25", "--layer", "0.25"});
  ASSERT_EQ(full.exit_code, 0) << full.err;

  EXPECT_NE(lean.out.find("cells   not classified: the formats asked hold contours and hatches "
                          "only\n"),
            std::string::npos)
      << lean.out;
  EXPECT_NE(lean.out.find("volume  mesh "), std::string::npos) << lean.out;
  EXPECT_NE(full.out.find(" interior, "), std::string::npos) << full.out;

  EXPECT_FALSE(fs::exists(tmp / "lean" / "ring.cells"));
  EXPECT_FALSE(fs::exists(tmp / "lean" / "ring.json"));
  for (const char* name : {"ring.cli", "ring.bin.cli"}) {
    const std::string bytes = read_file(tmp / "lean" / name);
    ASSERT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, read_file(tmp / "full" / name)) << name;
  }
  std::size_t svgs = 0;
  for (const auto& e : fs::directory_iterator(tmp / "lean" / "svg")) {
    ++svgs;
    EXPECT_EQ(read_file(e.path()), read_file(tmp / "full" / "svg" / e.path().filename()))
        << e.path().filename();
  }
  EXPECT_GT(svgs, 10u);
}

}  // namespace
}  // namespace strata
