#pragma once

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>

namespace strata {

/// The threads this run may use: the arena's, within a --threads limit (a global_control on
/// max_allowed_parallelism). What work is cut into one piece a thread asks.
inline std::size_t usable_threads() {
  return std::min(static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
                  tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

}  // namespace strata
