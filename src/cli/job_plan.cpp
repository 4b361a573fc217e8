#include "cli/job_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <system_error>
#include <thread>

namespace strata::cli {
namespace {

namespace fs = std::filesystem;

/// Larger than the build box of any printer on the market (sand-mould printers reach 1.8 m,
/// SPEC §2c): a model beyond it is in another unit (micrometres read as millimetres) or is no
/// part for a printer.
constexpr double kLargestBuildMm = 2000.0;

/// Cells a core classifies in a second of CPU time, fast kernel, cells file only: measured on
/// data/real/rear_case.stl with the default settings (199.3 M cells in 2.41 s of user time on
/// the README's 2-core machine, release build).
constexpr double kCellsPerCoreSecond = 80e6;
/// The PNG stack's extra time, the README's measured ratio (slice with PNGs / without).
constexpr double kPngTimeFactor = 1.49;

/// The least bytes a deflate stream of `raw` bytes takes: deflate codes at most 258 bytes in one
/// match of at least 2 bits, about 1032 to 1.
double deflated_at_least(double raw) { return std::ceil(raw / 1032.0); }

}  // namespace

JobPlan plan_job(const GridSpec& grid, const std::set<std::string>& formats, int threads) {
  JobPlan plan;
  const double nx = grid.nx, ny = grid.ny, nz = grid.nz;
  const double per_layer = nx * ny;
  plan.cells = per_layer * nz;
  auto add = [&](const char* format, double bytes, bool exact) {
    if (formats.count(format) == 0) return;
    plan.outputs.push_back({format, bytes, exact});
    plan.bytes_at_least += bytes;
  };
  // SPEC §3.1: an 80-byte header, then every layer padded to whole bytes at 2 bits a cell.
  add("cells", 80.0 + nz * std::ceil(per_layer / 4.0), true);
  // Two characters a cell and a newline a row, before the header and the layer lines.
  add("cells-ascii", nz * ny * (2.0 * nx + 1.0), false);
  // A PNG a layer: signature, IHDR, IDAT around zlib (2 + 4 bytes) and IEND are 63 bytes, the
  // pixels a filter byte a row and a byte a cell, deflated.
  add("png", nz * (63.0 + deflated_at_least(ny * (nx + 1.0))), false);
  add("svg", nz * 100.0, false);       // the svg element and its title alone
  add("cli", nz * 10.0, false);        // "$$LAYER/z\n" a layer
  add("cli-binary", nz * 6.0, false);  // the layer command and its z
  add("json", nz * 150.0, false);      // the keys of a layer's record
  add("html", 700e3 + deflated_at_least(plan.cells / 4.0), false);  // the page's code, the cells
  const double cores = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  plan.seconds =
      plan.cells / (kCellsPerCoreSecond * cores) * (formats.count("png") ? kPngTimeFactor : 1.0);
  return plan;
}

std::string bytes_text(double bytes) {
  static const char* const kUnits[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 1000.0 && unit < 6) {
    bytes /= 1000.0;
    ++unit;
  }
  return unit == 0 ? fmt::format("{:.0f} bytes", bytes)
                   : fmt::format("{:.1f} {}", bytes, kUnits[unit]);
}

namespace {

std::string count_text(double n) {
  if (n < 1e15) {
    std::string digits = fmt::format("{:.0f}", n);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
      if (i > 0 && (digits.size() - i) % 3 == 0) out.push_back(',');
      out.push_back(digits[i]);
    }
    return out;
  }
  return fmt::format("{:.3g}", n);
}

std::string duration_text(double seconds) {
  if (seconds < 1.0) return "under a second";
  if (seconds < 120.0) return fmt::format("about {:.0f} s", seconds);
  if (seconds < 2.0 * 3600.0) return fmt::format("about {:.0f} min", seconds / 60.0);
  if (seconds < 3.0 * 86400.0) return fmt::format("about {:.0f} h", seconds / 3600.0);
  return fmt::format("about {:.0f} days", seconds / 86400.0);
}

}  // namespace

std::string plan_text(const JobPlan& plan) {
  std::string outputs;
  for (const JobPlan::Output& o : plan.outputs) {
    if (!outputs.empty()) outputs += ", ";
    outputs += fmt::format("{} {}{}", o.format, o.exact ? "" : ">= ", bytes_text(o.bytes));
  }
  return fmt::format("{} cells; {}; {}", count_text(plan.cells),
                     outputs.empty() ? std::string("no file output") : outputs,
                     duration_text(plan.seconds));
}

std::string plan_json(const JobPlan& plan) {
  nlohmann::json outputs = nlohmann::json::object();
  for (const JobPlan::Output& o : plan.outputs) {
    outputs[o.format] = {{"bytes", o.bytes}, {"exact", o.exact}};
  }
  return nlohmann::json{{"cells", plan.cells},
                        {"outputs", outputs},
                        {"bytes_at_least", plan.bytes_at_least},
                        {"seconds_estimate", plan.seconds}}
      .dump();
}

std::optional<Error> check_free_space(const JobPlan& plan, const fs::path& dir) {
  // The folder may not exist yet: its nearest existing ancestor is on the same file system.
  std::error_code ec;
  fs::path existing = fs::absolute(dir, ec);
  if (ec) return std::nullopt;
  while (!fs::exists(existing, ec) && existing.has_parent_path() &&
         existing.parent_path() != existing) {
    existing = existing.parent_path();
  }
  const fs::space_info space = fs::space(existing, ec);
  if (ec || space.available == static_cast<std::uintmax_t>(-1)) return std::nullopt;
  const auto available = static_cast<double>(space.available);
  if (plan.bytes_at_least <= available) return std::nullopt;
  std::string parts;
  for (const JobPlan::Output& o : plan.outputs) {
    if (!parts.empty()) parts += ", ";
    parts += fmt::format("{} {}{}", o.format, o.exact ? "" : ">= ", bytes_text(o.bytes));
  }
  return Error{ErrorCode::BadInput,
               fmt::format("the outputs need at least {} ({}), but the file system has {} free; "
                           "nothing was written",
                           bytes_text(plan.bytes_at_least), parts, bytes_text(available)),
               dir.string()};
}

std::string size_text(const Bbox3& box) {
  return fmt::format("{:.6g} x {:.6g} x {:.6g} mm", box.max.x - box.min.x, box.max.y - box.min.y,
                     box.max.z - box.min.z);
}

std::optional<std::string> size_warning(const Bbox3& box, const Vec3& cell_mm) {
  if (box.empty()) return std::nullopt;
  const Vec3 size{box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z};
  const double largest = std::max({size.x, size.y, size.z});
  if (largest > kLargestBuildMm) {
    return fmt::format(
        "the model is {}, larger than any printer's build box: if its file is not "
        "in millimetres, give its unit with --units (cm, m, in, um) or a factor "
        "with --scale",
        size_text(box));
  }
  if (size.x < cell_mm.x && size.y < cell_mm.y && size.z < cell_mm.z) {
    return fmt::format(
        "the model is {}, smaller than one cell ({} x {} x {} mm): if its file "
        "is not in millimetres, give its unit with --units (cm, m, in) or a "
        "factor with --scale",
        size_text(box), cell_mm.x, cell_mm.y, cell_mm.z);
  }
  return std::nullopt;
}

}  // namespace strata::cli
