// The command line as a user runs it: outputs, exit codes, messages, no partial files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "strata/io/read_cells.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

using test::read_file;

std::size_t files_in(const fs::path& dir) {
  if (!fs::exists(dir)) return 0;
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
  return n;
}

TEST(SliceCommand, SlicesTheSampleRingWithDefaults) {
  TempDir tmp("cli");
  const auto run = run_cli({"slice", std::string(STRATA_DATA_DIR) + "/tetrahedron.stl", "-o",
                            (tmp / "out").string(), "--cell", "0.2", "--layer", "0.2"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("cells"), std::string::npos);
  EXPECT_TRUE(fs::exists(tmp / "out" / "tetrahedron.cells"));
  EXPECT_TRUE(fs::exists(tmp / "out" / "tetrahedron.json"));
  EXPECT_TRUE(fs::exists(tmp / "out" / "png" / "tetrahedron_00000.png"));
  EXPECT_EQ(files_in(tmp / "out" / "png"), 50u);
}

TEST(SliceCommand, AsciiAndBinaryStlGiveByteIdenticalCells) {
  TempDir tmp("cli");
  const TriangleSoup sphere = mesh::make_sphere(4.0, 3);
  ASSERT_TRUE(io::write_stl(tmp / "a.stl", sphere, io::StlEncoding::Ascii).has_value());
  ASSERT_TRUE(io::write_stl(tmp / "b.stl", sphere, io::StlEncoding::Binary).has_value());
  for (const char* name : {"a", "b"}) {
    const auto run = run_cli({"slice", (tmp / (std::string(name) + ".stl")).string(), "-o",
                              (tmp / name).string(), "--cell", "0.1", "--format", "cells", "-q"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const std::string a = read_file(tmp / "a" / "a.cells");
  ASSERT_GT(a.size(), 80u);
  EXPECT_EQ(a, read_file(tmp / "b" / "b.cells"));
}

TEST(SliceCommand, InfoReadsBackTheClassesThatSliceCounted) {
  TempDir tmp("cli");
  const auto run =
      run_cli({"slice", std::string(STRATA_DATA_DIR) + "/ring.stl", "-o", (tmp / "out").string(),
               "--cell", "0.4", "--layer", "0.4", "--format", "cells,cells-ascii,json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto binary = io::read_cells(tmp / "out" / "ring.cells");
  auto ascii = io::read_cells(tmp / "out" / "ring.cells.txt");
  ASSERT_TRUE(binary.has_value());
  ASSERT_TRUE(ascii.has_value());
  EXPECT_EQ(binary->cells, ascii->cells);
  const auto info = run_cli({"info", (tmp / "out" / "ring.cells").string(), "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const std::string report = read_file(tmp / "out" / "ring.json");
  std::size_t interior = 0;
  for (const CellClass c : binary->cells) interior += c == CellClass::Interior;
  EXPECT_NE(info.out.find("\"interior\": " + std::to_string(interior)), std::string::npos)
      << info.out;
  EXPECT_NE(report.find("\"interior\": " + std::to_string(interior)), std::string::npos);
}

TEST(SliceCommand, EveryFormatIsWritten) {
  TempDir tmp("cli");
  const auto run = run_cli({"slice", std::string(STRATA_DATA_DIR) + "/tetrahedron.stl", "-o",
                            (tmp / "out").string(), "--cell", "1", "--layer", "1", "--format",
                            "cells,cells-ascii,png,svg,cli,cli-binary,json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* f :
       {"tetrahedron.cells", "tetrahedron.cells.txt", "tetrahedron.cli", "tetrahedron.bin.cli",
        "tetrahedron.json", "png/tetrahedron_00009.png", "svg/tetrahedron_00009.svg"}) {
    EXPECT_TRUE(fs::exists(tmp / "out" / f)) << f;
  }
}

struct BadInput {
  std::string name;
  std::string bytes;
  std::string expected_in_message;
};

class SliceCommandBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SliceCommandBadInput, ExitsOneWithAMessageAndWritesNothing) {
  TempDir tmp("cli");
  const BadInput& c = GetParam();
  const fs::path model = tmp / (c.name + ".stl");
  std::ofstream(model, std::ios::binary) << c.bytes;
  const auto run = run_cli({"slice", model.string(), "-o", (tmp / "out").string()});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find(model.filename().string()), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(c.expected_in_message), std::string::npos) << run.err;
  EXPECT_EQ(files_in(tmp / "out"), 0u);
}

std::string binary_stl(std::uint32_t declared, std::uint32_t present) {
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&declared), 4);
  s.append(std::string(50 * present, '\0'));
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Files, SliceCommandBadInput,
    ::testing::Values(BadInput{"empty", "", ""}, BadInput{"truncated", binary_stl(100, 10), "100"},
                      BadInput{
                          "nan_vertex",
                          "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n",
                          ":5"},
                      BadInput{"no_facets", "solid x\nendsolid x\n", ""},
                      BadInput{"garbage", "this is not a mesh at all, just some text\n", ""}),
    [](const auto& info) { return info.param.name; });

// Issue 18: `1e999` in an ASCII PLY was read as 0 and the wrong part written with exit code 0.
TEST(SliceCommand, PlyCoordinateTooLargeForADoubleExitsOneAndWritesNothing) {
  for (const auto format : {test::TextMeshFormat::PlyFloat, test::TextMeshFormat::PlyDouble}) {
    for (const std::string token : {"1e999", "-1e999"}) {
      TempDir tmp("cli");
      const test::TextMesh mesh = test::triangle_with_x(format, token);
      const fs::path model = test::write_text_file(tmp / mesh.file_name, mesh.text);
      const auto run = run_cli({"slice", model.string(), "-o", (tmp / "out").string()});
      EXPECT_EQ(run.exit_code, 1) << run.err;
      EXPECT_EQ(run.err, "strata: " + model.string() + ":11: bad number '" + token +
                             "': too large for a double (|x| <= 1.7976931348623157e308)\n");
      EXPECT_EQ(files_in(tmp.path()), 1u) << "only the model itself";
    }
  }
}

TEST(SliceCommand, MissingFileIsBadInput) {
  TempDir tmp("cli");
  const auto run = run_cli({"slice", (tmp / "nope.stl").string(), "-o", (tmp / "out").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("nope.stl"), std::string::npos);
  EXPECT_FALSE(fs::exists(tmp / "out"));
}

TEST(SliceCommand, BadOptionsAreUsageErrors) {
  const std::string model = std::string(STRATA_DATA_DIR) + "/tetrahedron.stl";
  EXPECT_EQ(run_cli({"slice", model, "--cell", "-1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"slice", model, "--fill-rule", "sideways"}).exit_code, 2);
  EXPECT_EQ(run_cli({"slice", model, "--format", "gif"}).exit_code, 2);
  EXPECT_EQ(run_cli({"frobnicate"}).exit_code, 2);
}

TEST(SliceCommand, HelpExplainsTheOptions) {
  const auto run = run_cli({"slice", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* word :
       {"--layer", "--cell", "--shell-mode", "--fill-rule", "--scan-offset", "--format"}) {
    EXPECT_NE(run.out.find(word), std::string::npos) << word;
  }
}

}  // namespace
}  // namespace strata
