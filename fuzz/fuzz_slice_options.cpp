// The bytes as the options of a slice or validation request to `strata serve`: the JSON object
// the page sends, which `slice_options_of_json` turns into what `strata slice` would take. Every
// input must be answered, never by an exception. A refusal is a usage error that says why. Options
// it accepts must be ones the slicer takes (`to_slice_options` accepts them), and must say what the
// request said: each number given is the one set, each word given is the one set and one of its
// choices, each flag likewise, the origin its three numbers; an option left out (or null) keeps
// the command line's default; holes are filled only in a repair.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/serve_tasks.hpp"
#include "cli/slice_cli_options.hpp"
#include "fuzz_support.hpp"

namespace {

using nlohmann::json;
using strata::fuzz::check;

/// The request's value for `key`, or nullptr when it is absent or null (the default then holds).
const json* given(const json& request, const char* key) {
  const auto it = request.find(key);
  return it == request.end() || it->is_null() ? nullptr : &*it;
}

void check_number(const json& request, const char* key, const std::optional<double>& set,
                  const std::optional<double>& by_default) {
  const json* value = given(request, key);
  if (value == nullptr) {
    check(set == by_default, "an option left out keeps its default");
    return;
  }
  check(value->is_number() && set.has_value() && *set == value->get<double>(),
        "a number given is the number set");
}

template <class T>
void check_value(const json& request, const char* key, const T& set, const T& by_default) {
  const json* value = given(request, key);
  if (value == nullptr) {
    check(set == by_default, "an option left out keeps its default");
    return;
  }
  check(*value == json(set), "a word or flag given is the one set");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(strata::fuzz::as_bytes(data, size));
  const auto options = strata::cli::slice_options_of_json(text);
  if (!options) {
    check(options.error().code == strata::ErrorCode::Usage, "a refusal is a usage error");
    check(!options.error().message.empty(), "a refusal says why");
    return 0;
  }
  // Accepted: the text was a JSON object (the same parser, so the same reading of it).
  const json request = json::parse(text, nullptr, false);
  check(!request.is_discarded() && request.is_object(), "only a JSON object is accepted");
  const strata::cli::SliceCommandOptions defaults;
  const strata::cli::SliceCliOptions& s = options->slice;
  const strata::cli::SliceCliOptions& d = defaults.slice;
  check(strata::cli::to_slice_options(s).has_value(), "accepted options are ones slicing takes");

  check_number(request, "layer", s.layer_mm, d.layer_mm);
  check_number(request, "cell", s.cell_mm, d.cell_mm);
  check_number(request, "dx", s.dx_mm, d.dx_mm);
  check_number(request, "dy", s.dy_mm, d.dy_mm);
  check_number(request, "shell", s.shell_mm, d.shell_mm);
  check_number(request, "scan_offset", s.scan_offset_mm, d.scan_offset_mm);
  check_value(request, "shell_mode", s.shell_mode, d.shell_mode);
  check_value(request, "fill_rule", s.fill_rule, d.fill_rule);
  check_value(request, "kernel", options->kernel, defaults.kernel);
  check_value(request, "repair", options->repair, defaults.repair);
  check_value(request, "fill_holes", options->fill_holes, defaults.fill_holes);
  check_value(request, "origin", s.origin, d.origin);

  check(s.shell_mode == "distance" || s.shell_mode == "layers", "a shell mode of the choices");
  check(s.fill_rule == "nonzero" || s.fill_rule == "evenodd" || s.fill_rule == "winding",
        "a fill rule of the choices");
  check(options->kernel == "fast" || options->kernel == "exact", "a kernel of the choices");
  check(!options->fill_holes || options->repair, "holes are filled only in a repair");
  check(!(s.cell_mm && (s.dx_mm || s.dy_mm)), "a cell size excludes dx and dy");
  check(s.origin.empty() || s.origin.size() == 3, "an origin has three numbers");
  // Nothing else a request could set: the command line's other options keep their defaults.
  check(options->formats == defaults.formats && options->layers == defaults.layers &&
            s.threads == d.threads && options->model.empty() && options->output_dir.empty(),
        "a request sets only the options it may");
  return 0;
}
