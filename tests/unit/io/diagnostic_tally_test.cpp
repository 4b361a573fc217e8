// DiagnosticTally: one Diagnostic a warning kind, however often it occurs, with its count and
// the first few further places.
#include <gtest/gtest.h>

#include <string>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

TEST(DiagnosticTally, OneOccurrenceIsItsMessageAlone) {
  DiagnosticTally tally("line");
  tally.add("x.odd", Severity::Warning, 4, [] { return std::string("m.obj:4: odd"); });
  Diagnostics out;
  tally.flush_into(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].severity, Severity::Warning);
  EXPECT_EQ(out[0].code, "x.odd");
  EXPECT_EQ(out[0].message, "m.obj:4: odd");
}

TEST(DiagnosticTally, RepeatsAreCountedWithTheFirstEightFurtherPlaces) {
  DiagnosticTally tally("facet");
  int messages_made = 0;
  for (std::size_t facet = 10; facet < 21; ++facet) {
    tally.add("stl.bad_normal", Severity::Warning, facet, [&] {
      ++messages_made;
      return std::string("m.stl: facet 10: bad normal");
    });
  }
  Diagnostics out;
  tally.flush_into(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(messages_made, 1);  // the message is made for the first occurrence only
  EXPECT_EQ(out[0].message,
            "m.stl: facet 10: bad normal (11 times in all; also at facet 11, 12, 13, 14, 15, 16, "
            "17, 18, ...)");
}

TEST(DiagnosticTally, ExactlyNineOccurrencesListEveryPlace) {
  DiagnosticTally tally("line");
  for (std::size_t line = 1; line <= 9; ++line) {
    tally.add("x.odd", Severity::Info, line, [] { return std::string("first"); });
  }
  Diagnostics out;
  tally.flush_into(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].message, "first (9 times in all; also at line 2, 3, 4, 5, 6, 7, 8, 9)");
}

TEST(DiagnosticTally, KindsKeepTheOrderOfTheirFirstOccurrence) {
  DiagnosticTally tally("line");
  tally.add("b", Severity::Warning, 1, [] { return std::string("b at 1"); });
  tally.add("a", Severity::Info, 2, [] { return std::string("a at 2"); });
  tally.add("b", Severity::Warning, 3, [] { return std::string("b again"); });
  tally.add("a", Severity::Info, 4, [] { return std::string("a again"); });
  Diagnostics out;
  tally.flush_into(out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].code, "b");
  EXPECT_EQ(out[0].message, "b at 1 (2 times in all; also at line 3)");
  EXPECT_EQ(out[1].code, "a");
  EXPECT_EQ(out[1].severity, Severity::Info);
  EXPECT_EQ(out[1].message, "a at 2 (2 times in all; also at line 4)");
}

}  // namespace
}  // namespace strata::io::detail
