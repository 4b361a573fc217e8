#include <fmt/format.h>

#include <string>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {

bool DiagnosticTally::count_again(std::string_view code, std::size_t where) {
  for (auto& entry : entries_) {
    if (entry.code == code) {
      ++entry.count;
      if (entry.more.size() < kMaxPlaces) entry.more.push_back(where);
      return true;
    }
  }
  return false;
}

void DiagnosticTally::flush_into(Diagnostics& out) const {
  for (const auto& entry : entries_) {
    std::string message = entry.message;
    if (entry.count > 1) {
      message += fmt::format(" ({} times in all; also at {} {}{})", entry.count, place_kind_,
                             fmt::join(entry.more, ", "),
                             entry.count - 1 > entry.more.size() ? ", ..." : "");
    }
    out.push_back(Diagnostic{entry.severity, entry.code, std::move(message)});
  }
}

}  // namespace strata::io::detail
