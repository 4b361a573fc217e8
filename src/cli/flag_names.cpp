#include "cli/flag_names.hpp"

#include <string_view>

namespace strata::cli {

namespace {

/// A diagnostic whose message begins with an option in the library's words.
struct FlagPhrase {
  std::string_view code;
  std::string_view library;
  std::string_view command_line;
};

constexpr FlagPhrase kFlagPhrases[] = {
    {"shell.unequal_cell_sizes", "shell mode layers", "--shell-mode layers"},
};

}  // namespace

void name_flags(Diagnostics& diagnostics) {
  for (Diagnostic& d : diagnostics) {
    for (const FlagPhrase& p : kFlagPhrases) {
      if (d.code == p.code && d.message.starts_with(p.library)) {
        d.message.replace(0, p.library.size(), p.command_line);
      }
    }
  }
}

}  // namespace strata::cli
