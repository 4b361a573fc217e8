#include <fmt/format.h>

#include <cstdio>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/option_checks.hpp"
#include "cli/slice_cli_options.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/plan_layer_ranges.hpp"

namespace strata::cli {

namespace {

struct PlanOptions {
  std::string model;
  std::uint32_t parts = 1;
  SliceCliOptions slice;
  bool json = false;
};

int run_plan(const PlanOptions& o) {
  auto options = to_slice_options(o.slice);
  if (!options) return report_error(options.error());
  auto model = load_model(o.model, to_coordinate_scale(o.slice.units));
  if (!model) return report_error(model.error());
  auto grid = make_grid(model->mesh.bounds(), options->grid);
  if (!grid) return report_error(about_model(grid.error(), model->path));
  auto plan = plan_layer_ranges(model->mesh, *grid, o.parts);
  if (!plan) {
    return report_error(
        Error{ErrorCode::Usage, "--parts: " + plan.error().message, model->path.string()});
  }
  if (o.json) {
    nlohmann::json j;
    j["model"] = model->path.string();
    j["nz_total"] = plan->nz_total;
    j["cells_per_crossing_unit"] = kCellsPerCrossingUnit;
    nlohmann::json parts = nlohmann::json::array();
    for (std::size_t p = 0; p < plan->parts.size(); ++p) {
      const PlannedPart& part = plan->parts[p];
      parts.push_back({{"part", p},
                       {"first", part.layers.first},
                       {"end", part.layers.end},
                       {"layers", fmt::format("{}:{}", part.layers.first, part.layers.end)},
                       {"crossings", part.crossings},
                       {"work", part.work}});
    }
    j["parts"] = parts;
    std::fputs((j.dump(2) + "\n").c_str(), stdout);
    return kExitOk;
  }
  std::string out = fmt::format("model   {} ({} layers)\n", model->path.string(), plan->nz_total);
  out += "part      layers      first        end    crossings         work\n";
  for (std::size_t p = 0; p < plan->parts.size(); ++p) {
    const PlannedPart& part = plan->parts[p];
    out += fmt::format("{:4} {:>11} {:>10} {:>10} {:>12} {:>12}\n", p,
                       fmt::format("{}:{}", part.layers.first, part.layers.end), part.layers.first,
                       part.layers.end, part.crossings, part.work);
  }
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

}  // namespace

void register_plan_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Split a model's layers into ranges of balanced work for `slice --layers`");
  cmd->add_option("MODEL", options->model, "Mesh file: STL, OBJ, OFF, PLY, or .gz of one")
      ->required();
  cmd->add_option("--parts", options->parts, "Number of ranges")
      ->required()
      ->check(whole_number(1, std::numeric_limits<std::uint32_t>::max(), "number of parts"));
  add_slice_options(*cmd, options->slice);
  cmd->add_flag("--json", options->json, "Print JSON (for a scheduler) instead of a table");
  cmd->callback([options, &runner] { runner = [options] { return run_plan(*options); }; });
}

}  // namespace strata::cli
