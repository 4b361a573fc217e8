#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/option_checks.hpp"
#include "strata/io/read_cells.hpp"

namespace strata::cli {

namespace {

struct InfoOptions {
  std::string file;
  bool per_layer = false;
  bool json = false;
  std::vector<std::uint32_t> cell;  ///< --cell I,J,K
};

const char* class_words(CellClass c) {
  switch (c) {
    case CellClass::Empty:
      return "empty (00)";
    case CellClass::Interior:
      return "interior (01)";
    case CellClass::Boundary:
      return "boundary (11)";
  }
  return "reserved (10)";
}

/// `strata info FILE --cell I,J,K`: the class of one cell, reading layer by layer.
int run_cell(const InfoOptions& o) {
  const std::uint32_t i = o.cell[0], j = o.cell[1], k = o.cell[2];
  std::optional<CellClass> found;
  auto header = io::read_cells_layers(
      o.file,
      [&](const io::CellsHeader& h, std::uint32_t layer,
          std::span<const CellClass> cells) -> Result<void> {
        const GridSpec& g = h.grid;
        if (i >= g.nx || j >= g.ny || k >= g.nz) {
          return Error{ErrorCode::Usage,
                       fmt::format("--cell {},{},{} is outside the grid of {} x {} x {} cells", i,
                                   j, k, g.nx, g.ny, g.nz),
                       {}};
        }
        if (layer == k) found = cells[std::size_t{j} * g.nx + i];
        return {};
      });
  if (!header) return report_error(header.error());
  if (!found) return report_error(Error{ErrorCode::Internal, "the layer was not read", o.file});
  const GridSpec& g = header->grid;
  std::printf("cell %u,%u,%u %s at x=%.9g y=%.9g z=%.9g mm\n", i, j, k, class_words(*found),
              g.xc(i), g.yc(j), g.zk(k));
  return kExitOk;
}

/// The layer range of a part (SPEC §3.1b), from the slice report beside the cells file; nothing
/// for a whole run, a merged file, or a file without its report.
std::optional<nlohmann::json> part_range(const std::filesystem::path& cells_file,
                                         std::uint32_t nz) {
  std::string name = cells_file.filename().string();
  for (const char* ext : {".cells.txt", ".cells"}) {
    const std::string e = ext;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) {
      name.resize(name.size() - e.size());
      std::ifstream in(cells_file.parent_path() / (name + ".json"), std::ios::binary);
      if (!in) return std::nullopt;
      const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
      if (report.is_discarded() || !report.is_object() || !report.contains("range")) break;
      const nlohmann::json& r = report["range"];
      const auto whole_number = [&](const char* key) {
        return r.contains(key) && r[key].is_number_unsigned();
      };
      if (!r.is_object() || !whole_number("first") || !whole_number("end") ||
          !whole_number("nz_total")) {
        break;
      }
      const auto first = r["first"].get<std::uint32_t>();
      const auto end = r["end"].get<std::uint32_t>();
      // A report that does not describe this file (another run's) says nothing about it.
      if (end <= first || end - first != nz || end - first == r["nz_total"].get<std::uint32_t>()) {
        break;
      }
      return r;
    }
  }
  return std::nullopt;
}

int run_info(const InfoOptions& o) {
  if (!o.cell.empty()) return run_cell(o);
  auto summary = io::summarize_cells(o.file);
  if (!summary) return report_error(summary.error());
  const std::optional<nlohmann::json> range = part_range(o.file, summary->header.grid.nz);
  const std::uint32_t first_layer = range ? (*range)["first"].get<std::uint32_t>() : 0;
  const auto& h = summary->header;
  const GridSpec& g = h.grid;
  const auto& c = summary->class_counts;
  const double cell_volume = g.dx * g.dy * g.dz;
  if (o.json) {
    nlohmann::json j;
    j["file"] = o.file;
    j["grid"] = {{"nx", g.nx},
                 {"ny", g.ny},
                 {"nz", g.nz},
                 {"origin_mm", {g.x0, g.y0, g.z0}},
                 {"spacing_mm", {g.dx, g.dy, g.dz}}};
    j["shell_mm"] = h.shell_mm;
    if (range) j["range"] = *range;
    j["cells"] = {{"empty", c[0]}, {"interior", c[1]}, {"boundary", c[2]}};
    j["solid_volume_mm3"] = static_cast<double>(c[1] + c[2]) * cell_volume;
    if (o.per_layer) {
      nlohmann::json layers = nlohmann::json::array();
      for (const auto& l : summary->layer_counts) layers.push_back({l[0], l[1], l[2]});
      j["layers"] = layers;
    }
    std::fputs((j.dump(2) + "\n").c_str(), stdout);
    return kExitOk;
  }
  std::string out;
  out += fmt::format("file     {}\n", o.file);
  out += fmt::format("grid     {} x {} x {} cells ({} in all)\n", g.nx, g.ny, g.nz, g.cell_count());
  out += fmt::format("origin   ({}, {}, {}) mm\n", g.x0, g.y0, g.z0);
  out += fmt::format("spacing  {} x {} x {} mm\n", g.dx, g.dy, g.dz);
  out += fmt::format("shell    {} mm\n", h.shell_mm);
  if (range) {
    out +=
        fmt::format("range    layers {}..{} of the model's {} (a part; layer k here is {} + k)\n",
                    first_layer, (*range)["end"].get<std::uint32_t>() - 1,
                    (*range)["nz_total"].get<std::uint32_t>(), first_layer);
  }
  out +=
      fmt::format("cells    {} empty (00), {} interior (01), {} boundary (11)\n", c[0], c[1], c[2]);
  out += fmt::format("volume   {:.6g} mm3 solid\n", static_cast<double>(c[1] + c[2]) * cell_volume);
  if (summary->solid_bounds) {
    const auto& b = *summary->solid_bounds;
    out += fmt::format("solid    i {}..{}, j {}..{}, k {}..{}\n", b.i_min, b.i_max, b.j_min,
                       b.j_max, b.k_min, b.k_max);
  }
  if (o.per_layer) {
    out += "layer        z       empty    interior    boundary\n";
    for (std::size_t k = 0; k < summary->layer_counts.size(); ++k) {
      const auto& l = summary->layer_counts[k];
      out += fmt::format("{:5} {:>10.6g} {:>11} {:>11} {:>11}\n", k,
                         g.zk(static_cast<std::uint32_t>(k)), l[0], l[1], l[2]);
    }
  }
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

}  // namespace

void register_info_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd =
      app.add_subcommand("info", "Read a cells file (.cells or .cells.txt) back and summarise it");
  cmd->add_option("FILE", options->file, "A .cells or .cells.txt file")->required();
  cmd->add_flag("--layers", options->per_layer, "Also list the counts of every layer");
  cmd->add_flag("--json", options->json, "Print JSON instead of text");
  cmd->add_option("--cell", options->cell, "Print the class of cell I,J,K (0-based indices)")
      ->delimiter(',')
      ->expected(3)
      ->check(whole_number(0, std::numeric_limits<std::uint32_t>::max(), "cell index"));
  cmd->callback([options, &runner] { runner = [options] { return run_info(*options); }; });
}

}  // namespace strata::cli
