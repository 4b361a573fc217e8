// The names of the fill rules and shell modes, as the reports and the command line spell them.
#include "strata/slice/slice_options.hpp"

#include <gtest/gtest.h>

#include <string>

namespace strata {
namespace {

TEST(SliceOptions, FillRulesAreNamedAsOnTheCommandLine) {
  EXPECT_EQ(std::string(to_string(FillRule::NonZero)), "nonzero");
  EXPECT_EQ(std::string(to_string(FillRule::EvenOdd)), "evenodd");
  EXPECT_EQ(std::string(to_string(FillRule::Winding)), "winding");
}

TEST(SliceOptions, ShellModesAreNamedAsOnTheCommandLine) {
  EXPECT_EQ(std::string(to_string(ShellMode::Distance)), "distance");
  EXPECT_EQ(std::string(to_string(ShellMode::Layers)), "layers");
}

TEST(SliceOptions, DefaultsAreThoseOfTheReadme) {
  const SliceOptions o;
  EXPECT_EQ(o.grid.dx_mm, 0.1);
  EXPECT_EQ(o.grid.dy_mm, 0.1);
  EXPECT_EQ(o.grid.dz_mm, 0.1);
  EXPECT_FALSE(o.grid.origin.has_value());
  EXPECT_EQ(o.shell_mm, 0.5);
  EXPECT_EQ(o.shell_mode, ShellMode::Distance);
  EXPECT_EQ(o.fill_rule, FillRule::NonZero);
  EXPECT_EQ(o.scan_offset_mm, 0.0);
}

}  // namespace
}  // namespace strata
