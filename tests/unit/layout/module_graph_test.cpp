#include "support/module_graph.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strata::test {
namespace {

std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const std::string& p : problems) out += p + "\n";
  return out;
}

/// A small graph in the library's shape: core below slice below pipeline, each with a public
/// header and a private one.
std::vector<IncludeLine> clean_graph() {
  return {
      {"src/slice/slice_float.cpp", 1, "strata/slice/slice_float.hpp"},
      {"src/slice/slice_float.cpp", 3, "slice/grid_search_internal.hpp"},
      {"include/strata/slice/slice_float.hpp", 4, "strata/core/result.hpp"},
      {"src/pipeline/run_slice.cpp", 2, "strata/slice/slice_float.hpp"},
      {"src/pipeline/run_slice.cpp", 5, "predicates/filtered_sign.hpp"},
      {"src/predicates/filtered_sign.hpp", 2, "strata/core/result.hpp"},
      {"src/cli/main.cpp", 6, "cli/command.hpp"},
      {"src/cli/main.cpp", 7, "strata/pipeline/run_slice.hpp"},
      {"include/strata/strata.hpp", 3, "strata/pipeline/run_slice.hpp"},
      {"include/strata/core/result.hpp", 5, "strata/core/error.hpp"},
  };
}

TEST(ModuleGraph, TheLibraryIsOneWay) {
  const std::vector<IncludeLine> includes = read_includes(STRATA_SOURCE_DIR);
  ASSERT_GT(includes.size(), 100u) << "no sources found under " << STRATA_SOURCE_DIR;
  const std::vector<std::string> problems = check_module_graph(includes);
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(CheckModuleGraph, PassesACleanGraph) {
  const std::vector<std::string> problems = check_module_graph(clean_graph());
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(CheckModuleGraph, NamesEveryIncludeOfAPlantedCycle) {
  std::vector<IncludeLine> g = clean_graph();
  g.push_back({"src/slice/layer_plan.cpp", 9, "strata/pipeline/layer_sink.hpp"});
  const std::vector<std::string> problems = check_module_graph(g);
  ASSERT_EQ(problems.size(), 1u) << joined(problems);
  EXPECT_NE(problems[0].find("module cycle"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("src/slice/layer_plan.cpp:9"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("src/pipeline/run_slice.cpp:2"), std::string::npos) << problems[0];
}

TEST(CheckModuleGraph, FindsACycleThroughThreeModules) {
  std::vector<IncludeLine> g = clean_graph();
  g.push_back({"src/core/quiet.cpp", 4, "strata/predicates/filtered_sign.hpp"});
  g.push_back({"src/predicates/filtered_sign.hpp", 8, "slice/slice_float.hpp"});
  const std::vector<std::string> problems = check_module_graph(g);
  ASSERT_EQ(problems.size(), 1u) << joined(problems);
  EXPECT_NE(problems[0].find("module cycle"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("src/core/quiet.cpp:4"), std::string::npos) << problems[0];
}

TEST(CheckModuleGraph, NamesAPlantedInternalInclude) {
  std::vector<IncludeLine> g = clean_graph();
  g.push_back({"src/pipeline/fast_kernel.cpp", 5, "slice/grid_search_internal.hpp"});
  const std::vector<std::string> problems = check_module_graph(g);
  ASSERT_EQ(problems.size(), 1u) << joined(problems);
  EXPECT_NE(problems[0].find("src/pipeline/fast_kernel.cpp:5"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("internal header of module slice"), std::string::npos) << problems[0];
}

TEST(CheckModuleGraph, RefusesIncludesOfTheCommandLineAndTheFacade) {
  std::vector<IncludeLine> g = clean_graph();
  g.push_back({"src/pipeline/run_slice.cpp", 12, "cli/exit_code.hpp"});
  g.push_back({"src/slice/slice_float.cpp", 8, "strata/strata.hpp"});
  const std::vector<std::string> problems = check_module_graph(g);
  const std::string all = joined(problems);
  EXPECT_NE(all.find("src/pipeline/run_slice.cpp:12"), std::string::npos) << all;
  EXPECT_NE(all.find("nothing may include module cli"), std::string::npos) << all;
  EXPECT_NE(all.find("src/slice/slice_float.cpp:8"), std::string::npos) << all;
  EXPECT_NE(all.find("nothing may include module strata"), std::string::npos) << all;
}

TEST(ModuleOfFile, IsTheFolderBelowSrcOrIncludeStrata) {
  EXPECT_EQ(module_of_file("src/slice/slice_float.cpp"), "slice");
  EXPECT_EQ(module_of_file("include/strata/slice/grid_spec.hpp"), "slice");
  EXPECT_EQ(module_of_file("include/strata/strata.hpp"), "strata");
  EXPECT_EQ(module_of_file("tests/unit/slice/x_test.cpp"), "");
}

}  // namespace
}  // namespace strata::test
