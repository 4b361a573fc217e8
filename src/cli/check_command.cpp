#include <cstdio>
#include <memory>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/diagnose/mesh_report_json.hpp"
#include "strata/diagnose/mesh_report_text.hpp"
#include "strata/export/output_file.hpp"

namespace strata::cli {

namespace {

struct CheckOptions {
  std::string model;
  std::string json_file;
  bool json_stdout = false;
};

int run_check(const CheckOptions& o) {
  auto model = load_model(o.model);
  if (!model) return report_error(model.error());
  const diagnose::MeshReport report = diagnose::diagnose_mesh(model->mesh, model->soup);
  if (!o.json_file.empty()) {
    if (auto ok = io::write_text_file(o.json_file, diagnose::mesh_report_json(report) + "\n");
        !ok) {
      return report_error(ok.error());
    }
  }
  if (o.json_stdout) {
    std::fputs((diagnose::mesh_report_json(report) + "\n").c_str(), stdout);
  } else {
    std::fprintf(stdout, "model    %s (%s)\n", model->path.string().c_str(),
                 model->soup.format.c_str());
    for (const auto& d : model->soup.diagnostics)
      std::fprintf(stdout, "warning  %s\n", d.message.c_str());
    std::fputs(diagnose::mesh_report_text(report).c_str(), stdout);
  }
  return kExitOk;
}

}  // namespace

void register_check_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd =
      app.add_subcommand("check", "Report a mesh's defects and whether it can be printed as is");
  cmd->add_option("MODEL", options->model, "Mesh file: STL, OBJ, OFF, PLY, or .gz of one")
      ->required();
  auto* json_file = cmd->add_option("--json-file", options->json_file,
                                    "Also write the report as JSON to this file");
  cmd->add_flag("--json", options->json_stdout, "Print the report as JSON instead of text")
      ->excludes(json_file);
  cmd->callback([options, &runner] { runner = [options] { return run_check(*options); }; });
}

}  // namespace strata::cli
