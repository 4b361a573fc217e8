#pragma once

#include <string_view>

namespace strata::view::detail {

/// The viewer built from web/ (one HTML file, scripts and styles inlined), embedded at build
/// time. It holds kViewDataMarker exactly once, where the page's data goes.
std::string_view view_page_template();

inline constexpr std::string_view kViewDataMarker = "__STRATA_VIEW_DATA__";

}  // namespace strata::view::detail
