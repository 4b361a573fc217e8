#include "strata/core/quiet_cgal.hpp"

#include <CGAL/assertions.h>
#include <CGAL/assertions_behaviour.h>

namespace strata {

void make_cgal_failures_throw() {
  CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
  CGAL::set_warning_behaviour(CGAL::CONTINUE);
}

}  // namespace strata
