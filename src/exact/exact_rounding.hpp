#pragma once

// Shared by the exact path and validate's reference slicer: one rounding of exact values to
// doubles, so that equal exact points give equal doubles on both sides.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace strata::exact::detail {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Rational = CGAL::Epeck_ft;
static_assert(std::is_same_v<Kernel::FT::ET, Rational>, "Epeck's exact number type");

/// The GMP rational under q (valid while q lives).
mpq_srcptr raw_mpq(const Rational& q);

/// The double nearest to the GMP rational q (ties to even): the one rounding of a constructed
/// value. One integer division on per-thread scratch integers, no global state.
double round_to_double(mpq_srcptr q);
inline double round_to_double(const Rational& q) { return round_to_double(raw_mpq(q)); }

}  // namespace strata::exact::detail
