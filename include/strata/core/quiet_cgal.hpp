#pragma once

namespace strata {

/// Makes CGAL report failed preconditions and assertions by throwing (caught by the library and
/// turned into errors) instead of printing to stderr; call once at program start.
void make_cgal_failures_throw();

}  // namespace strata
