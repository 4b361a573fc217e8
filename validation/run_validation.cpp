// strata-validation: cross-validates the fast path against the exact path on the generated
// degenerate models and on the shared mesh corpus, and writes a Markdown report.
//
//   strata-validation [--quick] [--only TEXT] [--corpus DIR] [--max-bytes N] [--max-cells N]
//                     [--max-layers N] [--out FILE] [--write-models DIR] [--strict]
//
// Every model is validated under the nonzero and evenodd fill rules on two grids: one aligned
// with the model's features and one that is not. Exit codes: 0 every cell agrees, 4 some cell
// differs, 3 (with --strict) a path failed or refused a model, 2 bad usage, 1 the report could
// not be written. Closed 2-manifolds are also sliced by CGAL's Polygon_mesh_slicer (exact
// kernel), whose contours are compared with both paths'.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "models.hpp"
#include "report.hpp"
#include "runs.hpp"
#include "strata/core/quiet_cgal.hpp"
#include "strata/io/output_file.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using strata::validation::ModelCase;
using strata::validation::ModelCases;
using strata::validation::ModelRecord;
using strata::validation::RunnerOptions;
using strata::validation::RunRecord;

constexpr const char* kUsage =
    "usage: strata-validation [--quick] [--only TEXT] [--corpus DIR] [--max-bytes N]\n"
    "                         [--max-cells N] [--max-layers N] [--out FILE]\n"
    "                         [--write-models DIR] [--strict]\n"
    "\n"
    "Validates the fast slicing path against the exact (CGAL) path on the generated degenerate\n"
    "models and on every STL/OBJ/OFF/PLY mesh (also .gz) of the corpus, each under the nonzero\n"
    "and evenodd fill rules on an aligned and a shifted grid, and writes a Markdown report.\n"
    "Closed 2-manifolds (up to 200000 facets) are also sliced by CGAL's Polygon_mesh_slicer\n"
    "with the exact kernel, and its contours compared with both paths'.\n"
    "\n"
    "  --quick            generated models and about 10 small corpus files only\n"
    "  --only TEXT        only the models whose name contains TEXT (repeatable)\n"
    "  --corpus DIR       corpus folder with MANIFEST.tsv (default: ../shared/corpus)\n"
    "  --max-bytes N      skip corpus files larger than N bytes (default 5000000)\n"
    "  --max-cells N      cells per run at most, about (default 1000000)\n"
    "  --max-layers N     layers per run at most (default 64)\n"
    "  --out FILE         the report (default: validation/REPORT.md of the source tree)\n"
    "  --write-models DIR also write the generated models there as binary STL\n"
    "  --strict           exit 3 when a path failed or refused a model\n"
    "\n"
    "Exit codes: 0 every cell agrees, 4 some cell differs, 3 a path failed (--strict),\n"
    "2 bad usage, 1 the report could not be written.\n";

bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(out) && out > 0;
}

}  // namespace

int main(int argc, char** argv) {
  strata::make_cgal_failures_throw();
  RunnerOptions o;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto value = [&]() -> const char* {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "strata-validation: %s needs a value\n%s", arg.c_str(), kUsage);
        return nullptr;
      }
      return argv[++a];
    };
    double number = 0;
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--strict") {
      o.strict = true;
    } else if (arg == "--only") {
      const char* v = value();
      if (!v) return 2;
      o.only.emplace_back(v);
    } else if (arg == "--corpus") {
      const char* v = value();
      if (!v) return 2;
      o.corpus = v;
    } else if (arg == "--out") {
      const char* v = value();
      if (!v) return 2;
      o.out = v;
    } else if (arg == "--write-models") {
      const char* v = value();
      if (!v) return 2;
      o.write_models = v;
    } else if (arg == "--max-bytes" || arg == "--max-cells" || arg == "--max-layers") {
      const char* v = value();
      if (!v) return 2;
      if (!parse_number(v, number)) {
        std::fprintf(stderr, "strata-validation: %s takes a positive number\n%s", arg.c_str(),
                     kUsage);
        return 2;
      }
      if (arg == "--max-bytes") o.max_bytes = static_cast<std::uint64_t>(number);
      if (arg == "--max-cells") o.max_cells = number;
      if (arg == "--max-layers") o.max_layers = static_cast<std::uint32_t>(std::max(1.0, number));
    } else {
      std::fprintf(stderr, "strata-validation: unknown argument '%s'\n%s", arg.c_str(), kUsage);
      return 2;
    }
  }

  const auto started = Clock::now();
  ModelCases chosen;
  if (const std::optional<int> failed = strata::validation::collect_model_cases(o, chosen))
    return *failed;
  const std::vector<ModelCase>& cases = chosen.cases;

  std::vector<ModelRecord> records;
  bool any_differ = false, any_failure = false;
  for (std::size_t q = 0; q < cases.size(); ++q) {
    ModelRecord record = strata::validation::validate_case(cases[q], o);
    std::uint64_t differing = 0;
    double fast_s = 0, exact_s = 0;
    for (const RunRecord& r : record.runs) {
      differing += r.cells_differing;
      fast_s += r.fast_seconds;
      exact_s += r.exact_seconds;
      if (r.fast_error || r.exact_error) any_failure = true;
    }
    any_differ = any_differ || differing > 0;
    if (record.read_error) {
      std::fprintf(stderr, "[%zu/%zu] %s: unreadable: %s\n", q + 1, cases.size(),
                   record.model.name.c_str(), record.read_error->c_str());
    } else {
      std::fprintf(stderr,
                   "[%zu/%zu] %s: %zu runs, %llu cells differ, fast %.2f s, exact %.2f s%s\n",
                   q + 1, cases.size(), record.model.name.c_str(), record.runs.size(),
                   static_cast<unsigned long long>(differing), fast_s, exact_s,
                   std::any_of(record.runs.begin(), record.runs.end(),
                               [](const RunRecord& r) { return r.exact_error.has_value(); })
                       ? " (exact path refused or failed)"
                       : "");
    }
    records.push_back(std::move(record));
  }
  const double wall = std::chrono::duration<double>(Clock::now() - started).count();
  const std::string report = strata::validation::make_report(records, chosen.too_large, o, wall);
  if (o.out.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(o.out.parent_path(), ec);
  }
  if (auto ok = strata::io::write_text_file(o.out, report); !ok) {
    std::fprintf(stderr, "strata-validation: %s\n", ok.error().to_string().c_str());
    return 1;
  }
  std::fprintf(stderr, "strata-validation: report written to %s\n", o.out.string().c_str());
  if (any_differ) return 4;
  if (o.strict && any_failure) return 3;
  return 0;
}
