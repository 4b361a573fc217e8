// The conformance vectors of ../shared/vectors: a conforming `strata slice MODEL --format cells`
// with the listed options writes a byte-identical file, with either kernel.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;

struct Vector {
  std::string model;
  std::vector<std::string> options;
  std::string expected;
};

using test::read_file;

std::vector<std::string> opts(const char* cell, const char* layer, const char* shell,
                              const char* mode, const char* rule) {
  return {"--cell", cell,           "--layer", layer,         "--shell",
          shell,    "--shell-mode", mode,      "--fill-rule", rule};
}

const std::vector<Vector>& vectors() {
  static const std::vector<Vector> v = {
      {"tetrahedron", opts("1", "1", "1.5", "distance", "nonzero"),
       "tetrahedron__cell1_layer1_shell1.5_distance_nonzero.cells"},
      {"tetrahedron", opts("0.5", "0.25", "1", "layers", "nonzero"),
       "tetrahedron__cell0.5_layer0.25_shell1_layers_nonzero.cells"},
      {"stacked_boxes", opts("1", "1", "1", "layers", "nonzero"),
       "stacked_boxes__cell1_layer1_shell1_layers_nonzero.cells"},
      {"stacked_boxes", opts("0.5", "0.5", "0.6", "distance", "evenodd"),
       "stacked_boxes__cell0.5_layer0.5_shell0.6_distance_evenodd.cells"},
      {"walls_through_centres", opts("1", "1", "1", "layers", "nonzero"),
       "walls_through_centres__cell1_layer1_shell1_layers_nonzero.cells"},
      {"overlapping_boxes", opts("1", "1", "1", "layers", "nonzero"),
       "overlapping_boxes__cell1_layer1_shell1_layers_nonzero.cells"},
      {"overlapping_boxes", opts("1", "1", "1", "layers", "evenodd"),
       "overlapping_boxes__cell1_layer1_shell1_layers_evenodd.cells"},
  };
  return v;
}

class ConformanceVectors : public ::testing::TestWithParam<std::tuple<std::size_t, std::string>> {};

TEST_P(ConformanceVectors, CellsFileIsByteIdentical) {
  const auto& [index, kernel] = GetParam();
  const Vector& v = vectors()[index];
  const fs::path dir = fs::path(STRATA_SHARED_DIR) / "vectors";
  test::TempDir tmp("vectors");
  std::vector<std::string> args = {"slice",    (dir / (v.model + ".stl")).string(),
                                   "-o",       tmp.path().string(),
                                   "--format", "cells",
                                   "-q",       "--kernel",
                                   kernel};
  args.insert(args.end(), v.options.begin(), v.options.end());
  const auto run = test::run_cli(args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string expected = read_file(dir / v.expected);
  ASSERT_GT(expected.size(), 80u);
  EXPECT_TRUE(read_file(tmp / (v.model + ".cells")) == expected) << v.expected;
}

INSTANTIATE_TEST_SUITE_P(Shared, ConformanceVectors,
                         ::testing::Combine(::testing::Range<std::size_t>(0, 7),
                                            ::testing::Values("fast", "exact")),
                         [](const auto& info) {
                           std::string name = vectors()[std::get<0>(info.param)].expected;
                           name = name.substr(0, name.size() - 6) + "_" + std::get<1>(info.param);
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace strata
