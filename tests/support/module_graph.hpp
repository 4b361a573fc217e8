#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace strata::test {

/// One `#include "…"` line of the library.
struct IncludeLine {
  std::string file;      ///< relative to the checkout, e.g. "src/pipeline/run_slice.cpp"
  std::size_t line = 0;  ///< 1-based
  std::string target;    ///< what the quotes hold, e.g. "strata/voxel/boundary_shell.hpp"
};

/// The module a file of the library belongs to: the folder below src/ or include/strata/
/// ("src/slice/slice_float.cpp" and "include/strata/slice/grid_spec.hpp" are both "slice"); the
/// facade include/strata/strata.hpp is the module "strata"; "" for a file outside both.
std::string module_of_file(std::string_view file);

/// The checks of the one-way module graph, over the include lines of src/ and include/:
/// - no cycle between modules (a module including one that, through others, includes it);
/// - no include of another module's `*_internal.hpp` (a module shares code through public
///   headers or through headers of src/<module>/ without that suffix);
/// - no module includes `cli` (it holds main()) or the facade `strata/strata.hpp`.
/// A target names a module when its first folder (after "strata/") is the module of some file of
/// `includes`; other targets (a header of the same folder) are ignored.
/// @return one message a broken rule, each naming the include as file:line; empty when clean.
std::vector<std::string> check_module_graph(const std::vector<IncludeLine>& includes);

/// Every `#include "…"` line of the .hpp, .h and .cpp files under root/src and root/include,
/// with file names relative to root, in file name order.
std::vector<IncludeLine> read_includes(const std::filesystem::path& root);

}  // namespace strata::test
