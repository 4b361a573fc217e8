#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace strata::cli {

/// A one-line progress display on stderr, shown only when stderr is a terminal; redrawn at most
/// ten times a second.
class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  void update(std::uint32_t done, std::uint32_t total);

 private:
  std::string label_;
  bool enabled_ = false;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace strata::cli
