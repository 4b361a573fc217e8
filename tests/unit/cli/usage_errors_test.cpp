// Usage errors of the numeric options, through the command line: one line naming the option, the
// value and what it must be, exit code 2, and nothing read or written.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace strata {
namespace {

using test::run_cli;

struct UsageCase {
  std::vector<std::string> args;  ///< after the command and its model
  std::string message;            ///< the first line on stderr
};

/// Runs `strata <command> [model] args` and checks exit code 2 and the message.
void expect_usage_error(const std::string& command, const UsageCase& c) {
  std::vector<std::string> args{command};
  // No model is read before the options are checked: a missing file proves it.
  if (command != "serve" && command != "info") args.push_back("no-such-model.stl");
  if (command == "info") args.push_back("no-such.cells");
  args.insert(args.end(), c.args.begin(), c.args.end());
  const test::CliRun run = run_cli(args);
  std::string joined;
  for (const std::string& a : args) joined += " " + a;
  SCOPED_TRACE("strata" + joined);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err, "strata: " + c.message + "\nRun with --help for more information.\n");
  EXPECT_EQ(run.out, "");
}

const std::vector<UsageCase>& slice_option_cases() {
  static const std::vector<UsageCase> cases = {
      {{"--layer", "-1"}, "--layer: -1 is not a positive length in mm"},
      {{"--layer", "0"}, "--layer: 0 is not a positive length in mm"},
      {{"--layer", "-0"}, "--layer: -0 is not a positive length in mm"},
      {{"--layer", "abc"}, "--layer: bad number 'abc': not a number"},
      {{"--layer", "nan"},
       "--layer: bad number 'nan': not a number (inf and nan are not accepted)"},
      {{"--layer", "1e999"},
       "--layer: bad number '1e999': too large for a double (|x| <= 1.7976931348623157e308)"},
      {{"--cell", "-0.5"}, "--cell: -0.5 is not a positive length in mm"},
      {{"--dx", "0"}, "--dx: 0 is not a positive length in mm"},
      {{"--dy", "-2"}, "--dy: -2 is not a positive length in mm"},
      {{"--shell", "-1"}, "--shell: -1 is not a length in mm of 0 or more"},
      {{"--shell", "inf"},
       "--shell: bad number 'inf': not a number (inf and nan are not accepted)"},
      {{"--scan-offset", "nan"},
       "--scan-offset: bad number 'nan': not a number (inf and nan are not accepted)"},
      {{"--origin", "0,x,0"}, "--origin: bad number 'x': not a number"},
      {{"--threads", "-1"}, "--threads: -1 is not a number of threads from 0 to 2147483647"},
      {{"--threads", "1.5"},
       "--threads: bad number '1.5': not an integer (no decimal point or exponent where an "
       "integer is expected)"},
      {{"--threads", "99999999999999999999"},
       "--threads: 99999999999999999999 is not a number of threads from 0 to 2147483647"},
  };
  return cases;
}

TEST(UsageErrors, SliceOptionsNameTheOptionValueAndRange) {
  for (const UsageCase& c : slice_option_cases()) expect_usage_error("slice", c);
}

TEST(UsageErrors, ValidateAndViewShareTheSliceOptionMessages) {
  for (const char* command : {"validate", "view"}) {
    expect_usage_error(command, {{"--layer", "-1"}, "--layer: -1 is not a positive length in mm"});
    expect_usage_error(command,
                       {{"--shell", "-3"}, "--shell: -3 is not a length in mm of 0 or more"});
  }
}

TEST(UsageErrors, PageOptions) {
  for (const char* command : {"slice", "view"}) {
    expect_usage_error(command,
                       {{"--page-budget", "0"}, "--page-budget: 0 is not a positive size in MB"});
    expect_usage_error(command, {{"--page-facets", "10"},
                                 "--page-facets: 10 is not a number of facets from 1000 to "
                                 "50000000"});
  }
}

TEST(UsageErrors, ValidateCounts) {
  expect_usage_error("validate", {{"--max-listed", "-1"},
                                  "--max-listed: -1 is not a number of cells of 0 or more"});
  expect_usage_error("validate", {{"--reference-max-facets", "-5"},
                                  "--reference-max-facets: -5 is not a number of facets of 0 or "
                                  "more"});
}

TEST(UsageErrors, ServeOptions) {
  expect_usage_error("serve",
                     {{"--port", "70000"}, "--port: 70000 is not a port number from 0 to 65535"});
  expect_usage_error("serve",
                     {{"--port", "-1"}, "--port: -1 is not a port number from 0 to 65535"});
  expect_usage_error("serve",
                     {{"--max-upload", "-1"}, "--max-upload: -1 is not a positive size in MB"});
}

TEST(UsageErrors, InfoCellIndices) {
  expect_usage_error("info",
                     {{"--cell", "1,-1,0"}, "--cell: -1 is not a cell index from 0 to 4294967295"});
}

}  // namespace
}  // namespace strata
