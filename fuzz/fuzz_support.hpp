#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "strata/core/error.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

/// Helpers shared by the libFuzzer targets of fuzz/: small reading limits, checks of what the
/// readers promise, and a slice of every mesh read on a tiny grid.
namespace strata::fuzz {

/// Aborts with "fuzz check failed: `what`" (libFuzzer keeps the input).
[[noreturn]] void fail(const char* what);

/// fail(what) unless `condition` holds.
void check(bool condition, const char* what);

/// Limits small enough that no input makes a fuzz run allocate more than a few tens of MB.
io::ReadLimits read_limits();

/// The bytes libFuzzer hands over, as a string_view.
inline std::string_view as_bytes(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// FNV-1a of the bytes: picks the slicing options of an input, so that each input always runs
/// the same way.
std::uint64_t hash_bytes(std::string_view bytes);

/// Aborts with a message when a promise of the readers is broken: an error that is not
/// Error{BadInput} or has no message.
void check_read_error(const Error& error);

/// Aborts with a message when a successfully read soup breaks a promise of the readers: no
/// triangles, more than the limit, a non-finite coordinate, or normals not one per triangle.
void check_soup(const TriangleSoup& soup, const io::ReadLimits& limits);

/// Welds the soup and slices it with strata::slice_model on a grid of at most 64 x 64 x 16
/// cells spanning its bounding box, with options picked by `seed`, through a sink that checks
/// every layer. Skipped when a coordinate exceeds 1e15 mm; an axis along which the box is thinner
/// than 1e-30 mm (flat or denormal) gets one cell of 1 mm.
void slice_small(const TriangleSoup& soup, std::uint64_t seed);

/// Reads the bytes as a mesh file called `name` (its extension steers the format dispatch, as a
/// path's would), checks the result, and slices it when the read succeeds.
void read_and_slice(std::string_view bytes, std::string_view name);

}  // namespace strata::fuzz
