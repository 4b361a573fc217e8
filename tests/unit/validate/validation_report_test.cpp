// The report's names for people and machines, and the verdicts it derives from its figures.
#include "strata/validate/validation_report.hpp"

#include <gtest/gtest.h>

#include <string>

namespace strata::validate {
namespace {

TEST(ValidationReport, NamesEveryDifferenceReason) {
  EXPECT_STREQ(to_string(DifferenceReason::ScanOffset), "scan-offset");
  EXPECT_STREQ(to_string(DifferenceReason::Shell), "shell");
  EXPECT_STREQ(to_string(DifferenceReason::NearDegenerate), "near-degenerate");
  EXPECT_STREQ(to_string(DifferenceReason::FillRule), "fill-rule");
  EXPECT_STREQ(to_string(DifferenceReason::Unexplained), "unexplained");
}

TEST(ValidationReport, NamesEveryAreaMethod) {
  EXPECT_STREQ(to_string(AreaMethod::Identical), "identical");
  EXPECT_STREQ(to_string(AreaMethod::Arrangement), "arrangement");
  EXPECT_STREQ(to_string(AreaMethod::AreaOnly), "area-only");
  EXPECT_STREQ(to_string(AreaMethod::NotCompared), "not-compared");
}

TEST(ValidationReport, NamesEveryReasonTheReferenceSlicerSkips) {
  EXPECT_STREQ(to_string(ReferenceSkip::None), "none");
  EXPECT_STREQ(to_string(ReferenceSkip::Off), "off");
  EXPECT_STREQ(to_string(ReferenceSkip::TooManyFacets), "too-many-facets");
  EXPECT_STREQ(to_string(ReferenceSkip::Empty), "empty");
  EXPECT_STREQ(to_string(ReferenceSkip::NonManifold), "non-manifold");
  EXPECT_STREQ(to_string(ReferenceSkip::Inconsistent), "inconsistent-orientation");
  EXPECT_STREQ(to_string(ReferenceSkip::NotClosed), "not-closed");
  EXPECT_STREQ(to_string(ReferenceSkip::Failed), "failed");
}

TEST(ValidationReport, CellsAgreeOnlyWhenTheExactPathRanToTheEndAndNoCellDiffers) {
  ValidationReport r;
  EXPECT_TRUE(r.cells_agree());
  r.cells_differing = 1;
  EXPECT_FALSE(r.cells_agree());
  r.cells_differing = 0;
  r.exact_error = Error{ErrorCode::BadInput, "refused", ""};
  EXPECT_FALSE(r.cells_agree());
}

TEST(ValidationReport, GivesTheTimeRatioOnlyWhenBothPathsRanForSomeTime) {
  ValidationReport r;
  r.fast.seconds = 2.0;
  r.exact.seconds = 5.0;
  EXPECT_EQ(r.time_ratio(), 0.0) << "neither ran";
  r.fast.ran = true;
  EXPECT_EQ(r.time_ratio(), 0.0) << "the exact path did not run";
  r.exact.ran = true;
  EXPECT_EQ(r.time_ratio(), 2.5);
  r.fast.seconds = 0.0;
  EXPECT_EQ(r.time_ratio(), 0.0) << "no time to divide by";
}

TEST(LayerComparison, HasOpenChainsWhenEitherPathHasOne) {
  LayerComparison l;
  EXPECT_FALSE(l.has_open_chains());
  l.exact.open_chains = 1;
  EXPECT_TRUE(l.has_open_chains());
  l.exact.open_chains = 0;
  l.fast.open_chains = 2;
  EXPECT_TRUE(l.has_open_chains());
}

}  // namespace
}  // namespace strata::validate
