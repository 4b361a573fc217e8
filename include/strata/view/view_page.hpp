#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/diagnose/mesh_report.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/view/display_mesh.hpp"
#include "strata/view/view_stack.hpp"

namespace strata::view {

/// Everything the view page shows (web/DATA.md is the page's side of it).
struct ViewPage {
  std::string title;        ///< the model's stem
  std::string source_kind;  ///< "model" or "folder"
  std::string source_path;
  std::vector<std::string> notes;  ///< shown at the top of the page
  std::string report_json;         ///< the slice report (`<stem>.json`); empty when there is none
  std::optional<DisplayMesh> mesh;
  std::optional<diagnose::MeshReport> check;
  /// The model's mesh, to draw the facets that `check` names; may be null (then only its edge
  /// and vertex defects are drawn). Must outlive the calls below.
  const IndexedMesh* model_mesh = nullptr;
  ViewStack stack;
  std::string validation_json;  ///< `strata validate --json` output; empty when there is none
};

/// The page's data: one JSON object, with "</" escaped so that it can sit in a script element.
/// @return Error{BadInput} when report_json or validation_json is not JSON.
Result<std::string> view_page_data(const ViewPage& page);

/// The viewer with `data` (the page's data, or JSON the page understands) in place of its data
/// marker: a self-contained HTML page.
std::string view_page_with_data(std::string_view data);

/// Writes the page's data alone (the text of view_page_data) to `path` atomically, a piece at a
/// time rather than held whole. @return Error{BadInput} as view_page_data, or naming the path
/// when it cannot be written.
Result<void> write_view_page_data(const std::filesystem::path& path, const ViewPage& page);

/// Writes the self-contained page (the viewer with the data inlined) to `path` atomically.
/// @return Error{BadInput} naming the path when it cannot be written.
Result<void> write_view_page(const std::filesystem::path& path, const ViewPage& page);

}  // namespace strata::view
