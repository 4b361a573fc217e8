#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/merge_parts.hpp"

namespace strata::cli {

namespace {

struct MergeOptions {
  std::vector<std::string> parts;
  std::string output_dir;
  bool quiet = false;
};

int run_merge(const MergeOptions& o) {
  std::vector<std::filesystem::path> dirs(o.parts.begin(), o.parts.end());
  auto outcome = merge_parts(dirs, o.output_dir);
  if (!outcome) return report_error(outcome.error());
  if (!o.quiet) {
    std::fputs(fmt::format("merged  {} parts, layers 0..{} of {}\noutput  {}/: {}\n",
                           outcome->parts, outcome->nz_total - 1, outcome->stem, o.output_dir,
                           fmt::join(outcome->written, ", "))
                   .c_str(),
               stdout);
  }
  return kExitOk;
}

}  // namespace

void register_merge_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "merge",
      "Join the output folders of layer ranges (slice --layers) into those of the whole run");
  cmd->add_option("PART", options->parts,
                  "Output folders of `strata slice --layers`, in any order; each holds its report")
      ->required();
  cmd->add_option("-o,--output", options->output_dir, "Folder for the merged outputs")->required();
  cmd->add_flag("-q,--quiet", options->quiet, "Print nothing on success");
  cmd->callback([options, &runner] { runner = [options] { return run_merge(*options); }; });
}

}  // namespace strata::cli
