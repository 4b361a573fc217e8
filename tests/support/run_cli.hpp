#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace strata::test {

/// What one run of the strata executable did.
struct CliRun {
  int exit_code = -1;      ///< the process's exit status; -1 when it did not exit normally
  int term_signal = 0;     ///< the signal that ended it (0 when it exited)
  bool timed_out = false;  ///< killed with SIGKILL after the timeout
  std::string out;         ///< everything written to stdout
  std::string err;         ///< everything written to stderr
};

/// Where and how long run_cli runs the executable.
struct CliRunOptions {
  /// Working directory of the child; empty = the test's own.
  std::filesystem::path working_dir{};
  /// The child is killed (SIGKILL) once this has passed; the run reports timed_out.
  std::chrono::milliseconds timeout{std::chrono::seconds(120)};
};

/// The strata executable under test (the STRATA_CLI_PATH compile definition).
std::filesystem::path cli_path();

/// Runs the strata executable with `args` (without argv[0]) via fork/exec, feeding `stdin_text`
/// on its standard input (empty: /dev/null), capturing stdout and stderr in full, and waiting for
/// it to end or for the timeout. The environment is inherited.
/// Throws std::runtime_error when the process cannot be started at all (a missing executable
/// instead gives exit code 127 and a message on err).
CliRun run_cli(std::vector<std::string> args, std::string_view stdin_text = {},
               const CliRunOptions& options = {});

}  // namespace strata::test
