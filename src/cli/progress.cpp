#include "cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace strata::cli {

ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() {
  if (drawn_) std::fputs("\r\033[K", stderr);
}

void ProgressLine::update(std::uint32_t done, std::uint32_t total) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  drawn_ = true;
  std::fprintf(stderr, "\r%s: layer %u of %u (%.0f %%)\033[K", label_.c_str(), done, total,
               total ? 100.0 * done / total : 100.0);
  std::fflush(stderr);
}

}  // namespace strata::cli
