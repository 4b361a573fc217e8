#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/mesh/vec3.hpp"
#include "strata/slice/grid_spec.hpp"

namespace strata::cli {

/// What a slice job will make, known before it starts: the grid's cells, the size of every
/// output asked for and a time estimate.
struct JobPlan {
  /// One output format's size in bytes: exact for the cells files (their layout is fixed),
  /// a lower bound for the compressed and geometry-dependent ones.
  struct Output {
    std::string format;
    double bytes = 0.0;
    bool exact = false;
  };
  double cells = 0.0;  ///< nx * ny * nz, in double: it may exceed 2^64
  std::vector<Output> outputs;
  double bytes_at_least = 0.0;  ///< the sum of the outputs' sizes
  double seconds = 0.0;         ///< estimated slicing time on this machine's class of hardware
};

/// The plan of slicing on `grid` into `formats` (the names of `--format`) with `threads` worker
/// threads (0: every core).
JobPlan plan_job(const GridSpec& grid, const std::set<std::string>& formats, int threads);

/// One line: "3,200,000 cells; cells 800 kB, png >= 64.0 kB; about 1 s".
std::string plan_text(const JobPlan& plan);

/// The JSON report's record of the plan, as text of an object.
std::string plan_json(const JobPlan& plan);

/// Error{BadInput} located at `dir` when the outputs cannot fit the free space of the file
/// system `dir` is on (or would be made on), with both numbers; nothing otherwise (also when the
/// free space cannot be learnt).
std::optional<Error> check_free_space(const JobPlan& plan, const std::filesystem::path& dir);

/// A warning naming --units when the model's size suggests that its coordinates are not in
/// millimetres: larger than any printer's build box (over 2 m along an axis), or inside one
/// cell of `cell_mm` (dx, dy, dz); nothing for a plausible size.
std::optional<std::string> size_warning(const Bbox3& box, const Vec3& cell_mm);

/// "10 x 20 x 8 mm": the model's size for a report line.
std::string size_text(const Bbox3& box);

/// "12.3 MB" (powers of 1000, as file managers show).
std::string bytes_text(double bytes);

}  // namespace strata::cli
