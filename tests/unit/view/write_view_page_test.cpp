// The view page's data (web/DATA.md): the model's defects, the layers, the validation marks, the
// refusals of reports that are not JSON, and the page written around it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "strata/view/view_page.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"
#include "view/encode_internal.hpp"

namespace strata::view {
namespace {

using nlohmann::json;

json data_of(const ViewPage& page) {
  const Result<std::string> data = view_page_data(page);
  EXPECT_TRUE(data.has_value()) << data.error().to_string();
  return data ? json::parse(*data) : json();
}

/// Two triangles: (0,0,0) (1,0,0) (0,1,0) and (1,0,0) (1,1,0) (0,1,0).
IndexedMesh two_triangles() {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  return mesh;
}

std::string b64_floats(const std::vector<float>& values) {
  return detail::base64(detail::as_bytes(values));
}

TEST(ViewPageData, WritesTheHeaderOfAnEmptyPage) {
  ViewPage page;
  page.title = "ring";
  page.source_kind = "model";
  page.source_path = "data/ring.stl";
  page.notes = {"first"};
  page.stack.notes = {"second"};
  page.stack.grid = GridSpec{-1, -2, 0, 0.5, 0.25, 0.125, 4, 3, 2};
  page.stack.shell_mm = 0.5;
  const json j = data_of(page);
  EXPECT_EQ(j.at("format"), "strata-view");
  EXPECT_EQ(j.at("version"), 1);
  EXPECT_EQ(j.at("title"), "ring");
  EXPECT_EQ(j.at("source"), json::parse(R"({"kind": "model", "path": "data/ring.stl"})"));
  EXPECT_EQ(j.at("notes"), json::parse(R"(["first", "second"])"));
  EXPECT_EQ(j.at("grid"), json::parse(R"({"nx": 4, "ny": 3, "nz": 2, "x0": -1, "y0": -2, "z0": 0,
                                          "dx": 0.5, "dy": 0.25, "dz": 0.125})"));
  EXPECT_EQ(j.at("shell_mm"), 0.5);
  EXPECT_TRUE(j.at("report").is_null());
  EXPECT_TRUE(j.at("mesh").is_null());
  EXPECT_TRUE(j.at("check").is_null());
  EXPECT_TRUE(j.at("volume").is_null()) << "a model checked, not sliced";
  EXPECT_TRUE(j.at("validation").is_null());
  EXPECT_EQ(j.at("layers"), json::parse(R"({"encoding": "2bit-msb-zlib", "stored": [],
      "stride": 1, "cells": [], "contours": [], "hatches": null})"));
}

TEST(ViewPageData, WritesTheLayersAsTheJsonLibraryWouldCharacterForCharacter) {
  // The layers' text is written directly, not through the JSON library: it must be what the
  // library writes for the same values, with and without scanline segments.
  for (const bool with_hatches : {true, false}) {
    ViewPage page;
    page.title = "\x01strata-layers-0\x01";  // the layers' marker in a name stays the name
    page.source_path = R"("layers":"\u0001strata-layers-0\u0001")";
    ViewStack& s = page.stack;
    s.stored = {0, 3, 6};
    s.stride = 3;
    s.has_hatches = with_hatches;
    s.cells_zlib = {std::string("\x78\x9c\x03\x00", 4), "ab", std::string(100, '\xff')};
    s.contours = {
        {},
        {ViewLoop{LoopKind::Outer, {0, 0, 1, 0, 1, 1}},
         ViewLoop{LoopKind::Hole, {0.25f, 0.25f, 0.5f, 0.25f}}, ViewLoop{LoopKind::Open, {}}},
        {ViewLoop{LoopKind::Open, {-1.5f, 2e-7f}}}};
    s.hatches = {{0.5f, 0.125f, 2.0f, 0.125f}, {}, {1, 2, 3, 4, 5, 6, 7, 8}};
    json expected_contours = json::array();
    for (const auto& loops : s.contours) {
      json layer = json::array();
      for (const ViewLoop& loop : loops) {
        const char* kind = loop.kind == LoopKind::Outer  ? "outer"
                           : loop.kind == LoopKind::Hole ? "hole"
                                                         : "open";
        layer.push_back({{"kind", kind}, {"points", detail::base64(detail::as_bytes(loop.xy))}});
      }
      expected_contours.push_back(layer);
    }
    json expected_hatches = json::array();
    for (const auto& h : s.hatches) expected_hatches.push_back(detail::base64(detail::as_bytes(h)));
    json expected_cells = json::array();
    for (const auto& c : s.cells_zlib) expected_cells.push_back(detail::base64(c));
    const json expected = {{"encoding", "2bit-msb-zlib"},
                           {"stored", s.stored},
                           {"stride", s.stride},
                           {"cells", expected_cells},
                           {"contours", expected_contours},
                           {"hatches", with_hatches ? expected_hatches : json(nullptr)}};
    const Result<std::string> data = view_page_data(page);
    ASSERT_TRUE(data.has_value());
    EXPECT_NE(data->find(R"("layers":)" + expected.dump() + ","), std::string::npos) << *data;
    EXPECT_EQ(json::parse(*data).at("layers"), expected);
    EXPECT_EQ(json::parse(*data).at("title"), page.title);
    EXPECT_EQ(json::parse(*data).at("source").at("path"), page.source_path);
  }
}

TEST(ViewPageData, EscapesTheEndOfAScriptElement) {
  ViewPage page;
  page.title = "a</script><b";
  const Result<std::string> data = view_page_data(page);
  ASSERT_TRUE(data.has_value());
  EXPECT_EQ(data->find("</"), std::string::npos) << *data;
  EXPECT_NE(data->find(R"("title":"a<\/script><b")"), std::string::npos) << *data;
  EXPECT_EQ(json::parse(*data).at("title"), "a</script><b");
  // Several, side by side, first and last: each "</" becomes "<\/".
  page.title = "</</a<</";
  const Result<std::string> many = view_page_data(page);
  ASSERT_TRUE(many.has_value());
  EXPECT_EQ(many->find("</"), std::string::npos) << *many;
  EXPECT_NE(many->find(R"("title":"<\/<\/a<<\/")"), std::string::npos) << *many;
  EXPECT_EQ(json::parse(*many).at("title"), "</</a<</");
}

TEST(ViewPageData, ReplacesInvalidUtf8InANameInsteadOfRefusingIt) {
  ViewPage page;
  page.source_path = "models/\xff.stl";
  EXPECT_EQ(data_of(page).at("source").at("path"), "models/\xef\xbf\xbd.stl");
}

TEST(ViewPageData, EmbedsTheSliceReport) {
  ViewPage page;
  page.report_json = R"({"layers": 3})";
  EXPECT_EQ(data_of(page).at("report"), json::parse(R"({"layers": 3})"));
}

TEST(ViewPageData, RefusesASliceReportThatIsNotJson) {
  ViewPage page;
  page.source_path = "out/ring-strata";
  page.report_json = "{\"layers\": ";
  const Result<std::string> data = view_page_data(page);
  ASSERT_FALSE(data.has_value());
  EXPECT_EQ(data.error().code, ErrorCode::BadInput);
  EXPECT_EQ(data.error().to_string(), "out/ring-strata: the slice report is not JSON");
}

TEST(ViewPageData, RefusesAValidationReportThatIsNotJson) {
  ViewPage page;
  page.source_path = "out/ring-strata";
  page.validation_json = "verdict: agree";
  const Result<std::string> data = view_page_data(page);
  ASSERT_FALSE(data.has_value());
  EXPECT_EQ(data.error().code, ErrorCode::BadInput);
  EXPECT_EQ(data.error().to_string(), "out/ring-strata: the validation report is not JSON");
}

TEST(ViewPageData, EncodesTheDisplayMesh) {
  ViewPage page;
  DisplayMesh mesh;
  mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  mesh.indices = {0, 1, 2};
  mesh.facets_in_model = 10;
  mesh.simplified = true;
  page.mesh = mesh;
  const json m = data_of(page).at("mesh");
  EXPECT_EQ(m.at("facets_in_model"), 10);
  EXPECT_EQ(m.at("facets_shown"), 1);
  EXPECT_TRUE(m.at("simplified").get<bool>());
  EXPECT_EQ(m.at("positions"), b64_floats(mesh.positions));
  EXPECT_EQ(m.at("indices"), detail::base64(detail::as_bytes(mesh.indices)));
}

diagnose::MeshReport report_with_every_defect() {
  diagnose::MeshReport r;
  r.verdict = diagnose::Verdict::NeedsRepair;
  r.verdict_reason = "1 open edge in 1 loop";
  r.num_facets = 2;
  r.shells.resize(1);
  r.self_intersections_checked = true;
  r.boundary_edges = {3, {{{0, 0, 0}, {1, 0, 0}}}};  // three found, one located
  r.non_manifold_edges = {1, {{{1, 0, 0}, {0, 1, 0}}}};
  r.inconsistent_edges = {1, {{{1, 1, 0}, {0, 1, 0}}}};
  r.degenerate_facets = {2, {1, 7}};  // facet 7 is not in the mesh: not drawn
  r.flipped_normals = {1, {0}};
  r.self_intersections = {1, {{0, 1}}};
  r.non_manifold_vertices = {1, {{1, 0, 0}}};
  return r;
}

TEST(ViewPageData, DrawsEveryDefectOfTheCheckOnTheModel) {
  const IndexedMesh mesh = two_triangles();
  ViewPage page;
  page.check = report_with_every_defect();
  page.model_mesh = &mesh;
  const json check = data_of(page).at("check");
  EXPECT_EQ(check.at("verdict"), "needs-repair");
  EXPECT_EQ(check.at("reason"), "1 open edge in 1 loop");
  EXPECT_TRUE(check.at("self_intersections_checked").get<bool>());
  EXPECT_EQ(check.at("facets"), 2);
  EXPECT_EQ(check.at("shells"), 1);
  const std::vector<float> first = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<float> second = {1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<float> both = first;
  both.insert(both.end(), second.begin(), second.end());
  const json expected = {
      {{"kind", "open_edges"},
       {"label", "open edges"},
       {"count", 3},
       {"shape", "segments"},
       {"data", b64_floats({0, 0, 0, 1, 0, 0})},
       {"shown", 1}},
      {{"kind", "non_manifold_edges"},
       {"label", "non-manifold edges"},
       {"count", 1},
       {"shape", "segments"},
       {"data", b64_floats({1, 0, 0, 0, 1, 0})},
       {"shown", 1}},
      {{"kind", "inconsistent_edges"},
       {"label", "edges of flipped neighbours"},
       {"count", 1},
       {"shape", "segments"},
       {"data", b64_floats({1, 1, 0, 0, 1, 0})},
       {"shown", 1}},
      {{"kind", "degenerate_facets"},
       {"label", "degenerate facets"},
       {"count", 2},
       {"shape", "triangles"},
       {"data", b64_floats(second)},
       {"shown", 1}},
      {{"kind", "flipped_normals"},
       {"label", "facets against their stored normal"},
       {"count", 1},
       {"shape", "triangles"},
       {"data", b64_floats(first)},
       {"shown", 1}},
      {{"kind", "self_intersections"},
       {"label", "self-intersecting facets"},
       {"count", 1},
       {"shape", "triangles"},
       {"data", b64_floats(both)},
       {"shown", 2}},
      {{"kind", "non_manifold_vertices"},
       {"label", "non-manifold vertices"},
       {"count", 1},
       {"shape", "points"},
       {"data", b64_floats({1, 0, 0})},
       {"shown", 1}},
  };
  EXPECT_EQ(check.at("defects"), expected);
}

TEST(ViewPageData, DrawsOnlyTheEdgeAndVertexDefectsWithoutTheModel) {
  ViewPage page;
  page.check = report_with_every_defect();
  const json defects = data_of(page).at("check").at("defects");
  std::vector<std::string> kinds;
  for (const json& d : defects) kinds.push_back(d.at("kind"));
  EXPECT_EQ(kinds, (std::vector<std::string>{"open_edges", "non_manifold_edges",
                                             "inconsistent_edges", "non_manifold_vertices"}));
}

TEST(ViewPageData, ListsNoDefectOfACleanModel) {
  const IndexedMesh mesh = two_triangles();
  ViewPage page;
  page.check = diagnose::MeshReport{};
  page.model_mesh = &mesh;
  const json check = data_of(page).at("check");
  EXPECT_EQ(check.at("verdict"), "printable");
  EXPECT_TRUE(check.at("defects").empty());
}

ViewStack two_layer_stack(bool hatches) {
  ViewStack s;
  s.grid = GridSpec{0, 0, 0, 1, 1, 1, 2, 2, 4};
  s.stored = {0, 2};
  s.stride = 2;
  s.cells_zlib = {"\x01\x02", "\x03"};
  s.contours = {{ViewLoop{LoopKind::Outer, {0, 0, 1, 0, 1, 1}}, ViewLoop{LoopKind::Hole, {0.5f}}},
                {ViewLoop{LoopKind::Open, {2, 2}}}};
  s.has_hatches = hatches;
  s.hatches = {{0, 0.5f, 1, 0.5f}, {}};
  s.volume.nx = 1;
  s.volume.ny = 1;
  s.volume.nz = 2;
  s.volume.bz = 2;
  s.volume.blocks = {3, 1};
  return s;
}

TEST(ViewPageData, EncodesTheStoredLayersAndTheVolume) {
  ViewPage page;
  page.stack = two_layer_stack(true);
  const json j = data_of(page);
  const json& layers = j.at("layers");
  EXPECT_EQ(layers.at("stored"), json::parse("[0, 2]"));
  EXPECT_EQ(layers.at("stride"), 2);
  EXPECT_EQ(layers.at("cells"), json({detail::base64("\x01\x02"), detail::base64("\x03")}));
  const json contours = {
      {{{"kind", "outer"}, {"points", b64_floats({0, 0, 1, 0, 1, 1})}},
       {{"kind", "hole"}, {"points", b64_floats({0.5f})}}},
      {{{"kind", "open"}, {"points", b64_floats({2, 2})}}},
  };
  EXPECT_EQ(layers.at("contours"), contours);
  EXPECT_EQ(layers.at("hatches"), json({b64_floats({0, 0.5f, 1, 0.5f}), b64_floats({})}));
  const json& volume = j.at("volume");
  EXPECT_EQ(volume.at("nx"), 1);
  EXPECT_EQ(volume.at("nz"), 2);
  EXPECT_EQ(volume.at("bz"), 2);
  EXPECT_EQ(volume.at("data"), detail::base64(detail::zlib_compress(std::string("\x03\x01", 2))));
}

TEST(ViewPageData, EscapesTheEndOfAScriptElementOnBothSidesOfTheLayers) {
  // The layers' text is written apart from the document around it, which is escaped in two
  // pieces: the check comes before "layers" in the JSON, the title after it.
  ViewPage page;
  page.stack = two_layer_stack(true);
  diagnose::MeshReport check;
  check.verdict_reason = "open</edge";
  page.check = check;
  page.title = "</title";
  const Result<std::string> data = view_page_data(page);
  ASSERT_TRUE(data.has_value());
  EXPECT_EQ(data->find("</"), std::string::npos) << *data;
  const json j = json::parse(*data);
  EXPECT_EQ(j.at("check").at("reason"), "open</edge");
  EXPECT_EQ(j.at("title"), "</title");
  EXPECT_EQ(j.at("layers").at("stored"), json::parse("[0, 2]"));
}

TEST(ViewPageData, KeepsANameThatHoldsTheTextOfAMarker) {
  // The long values stand in the document as markers (control characters, "\u0001strata-...")
  // until their text replaces them. A name or note holding the same text (a file name may hold
  // control characters) stays itself, and every value is still in its place: the notes, the
  // report and the title come before the volume's place in the document, and the report has a
  // "layers" of its own.
  ViewPage page;
  page.stack = two_layer_stack(true);
  page.mesh = DisplayMesh{{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}, 1, false};
  json report = json::object();
  // The markers of the first two salts, so that the document is composed three times.
  std::vector<std::string> names;
  for (int salt = 0; salt < 2; ++salt) {
    for (int k = 0; k < 5; ++k) names.push_back(fmt::format("\x01strata-held-{}-{}\x01", salt, k));
    names.push_back(fmt::format("\x01strata-layers-{}\x01", salt));
  }
  for (std::size_t n = 0; n < names.size(); ++n) report[fmt::format("name{}", n)] = names[n];
  report["layers"] = names.back();
  page.report_json = report.dump();
  page.title = names[0];
  page.notes = names;
  const json j = data_of(page);
  EXPECT_EQ(j.at("report"), report);
  EXPECT_EQ(j.at("title"), names[0]);
  EXPECT_EQ(j.at("notes"), json(names));
  EXPECT_EQ(j.at("mesh").at("positions"), b64_floats(page.mesh->positions));
  EXPECT_EQ(j.at("mesh").at("indices"), detail::base64(detail::as_bytes(page.mesh->indices)));
  EXPECT_EQ(j.at("volume").at("data"),
            detail::base64(detail::zlib_compress(std::string("\x03\x01", 2))));
  EXPECT_EQ(j.at("layers").at("stored"), json::parse("[0, 2]"));
}

TEST(ViewPageData, WritesNoHatchesWhenTheStackLeftThemOut) {
  ViewPage page;
  page.stack = two_layer_stack(false);
  EXPECT_TRUE(data_of(page).at("layers").at("hatches").is_null());
}

TEST(ViewPageData, MarksTheCellsAndLayersTheValidationFoundDiffering) {
  ViewPage page;
  page.validation_json = R"({"cells": {"compared": 24, "differing": 4, "differences": [
      {"i": 1, "j": 2, "k": 3, "fast": "11", "exact": "01"},
      {"i": 0, "j": 0, "k": 1, "fast": "01", "exact": "00"},
      {"i": 1, "j": 0, "k": 3, "fast": "10", "exact": 3},
      {"k": 1}]}})";
  EXPECT_EQ(data_of(page).at("validation"), json::parse(R"({"cells_compared": 24,
      "cells_differing": 4, "layers_differing": [1, 3],
      "cells": [[1, 2, 3, 3, 1], [0, 0, 1, 1, 0], [1, 0, 3, 0, 0], [0, 0, 1, 0, 0]]})"));
}

TEST(ViewPageData, ReadsAValidationReportWithoutCellsAsNothingDiffering) {
  ViewPage page;
  page.validation_json = R"({"verdict": "exact-path-failed"})";
  EXPECT_EQ(data_of(page).at("validation"), json::parse(R"({"cells_compared": 0,
      "cells_differing": 0, "layers_differing": [], "cells": []})"));
  page.validation_json = R"({"cells": {"compared": 8, "differing": 0, "differences": null}})";
  EXPECT_EQ(data_of(page).at("validation"), json::parse(R"({"cells_compared": 8,
      "cells_differing": 0, "layers_differing": [], "cells": []})"));
}

TEST(ViewPageWithData, PutsTheDataInPlaceOfTheMarkerOnce) {
  const std::string data = R"({"format": "probe-7f3a"})";
  const std::string page = view_page_with_data(data);
  EXPECT_EQ(page.find("__STRATA_VIEW_DATA__"), std::string::npos);
  const std::size_t at = page.find(data);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(page.find("probe-7f3a", at + data.size()), std::string::npos);
  EXPECT_EQ(page.find("probe-7f3a"), at + 12);
  EXPECT_EQ(page.rfind("<!doctype html>", 0), 0u) << page.substr(0, 40);
}

TEST(WriteViewPage, WritesThePageWithItsData) {
  test::TempDir dir("view-page");
  ViewPage page;
  page.title = "probe-8c1d";
  ASSERT_TRUE(write_view_page(dir / "page.html", page).has_value());
  const std::string written = test::read_file(dir / "page.html");
  EXPECT_EQ(written, view_page_with_data(*view_page_data(page)));
}

TEST(WriteViewPage, WritesALargePageInPiecesThatJoinIntoItsData) {
  // The page is written a piece at a time: the base64 of a long value in pieces of raw bytes,
  // the layers in batches made in parallel. Values long enough for several pieces and batches,
  // of lengths that are not multiples of 3, must read back as their whole encodings.
  std::mt19937 random(7);
  const auto bytes = [&](std::size_t n) {
    std::string out(n, '\0');
    for (char& c : out) c = static_cast<char>(random());
    return out;
  };
  ViewPage page;
  page.title = "pieces";
  DisplayMesh mesh;
  for (std::size_t i = 0; i < 3 * 70'001; ++i) mesh.positions.push_back(0.001f * i);
  for (std::uint32_t i = 0; i < 3 * 90'001; ++i) mesh.indices.push_back(i % 70'001);
  page.mesh = mesh;
  ViewStack& s = page.stack;
  s.grid = GridSpec{0, 0, 0, 1, 1, 1, 2, 2, 60};
  s.has_hatches = true;
  for (std::uint32_t k = 0; k < 60; ++k) {
    s.stored.push_back(k);
    s.cells_zlib.push_back(bytes(40'000 + 7 * k));
    s.contours.push_back({ViewLoop{LoopKind::Outer, std::vector<float>(20'000 + k, 0.5f * k)},
                          ViewLoop{LoopKind::Hole, std::vector<float>(k, -1.0f)}});
    s.hatches.push_back(std::vector<float>(4 * (k % 5), 2.0f * k));
  }
  s.volume.nx = s.volume.ny = 500;
  s.volume.nz = 2;
  s.volume.blocks.resize(500 * 500 * 2);
  for (auto& b : s.volume.blocks) b = static_cast<std::uint8_t>(random() % 4);

  test::TempDir dir("view-page");
  ASSERT_TRUE(write_view_page(dir / "page.html", page).has_value());
  const std::string written = test::read_file(dir / "page.html");
  const Result<std::string> data = view_page_data(page);
  ASSERT_TRUE(data.has_value());
  EXPECT_EQ(written, view_page_with_data(*data));
  ASSERT_TRUE(write_view_page_data(dir / "view.json", page).has_value());
  EXPECT_EQ(test::read_file(dir / "view.json"), *data);

  const json j = json::parse(*data);
  EXPECT_EQ(j.at("mesh").at("positions"), b64_floats(mesh.positions));
  EXPECT_EQ(j.at("mesh").at("indices"), detail::base64(detail::as_bytes(mesh.indices)));
  const std::string_view volume_bytes(reinterpret_cast<const char*>(s.volume.blocks.data()),
                                      s.volume.blocks.size());
  EXPECT_EQ(j.at("volume").at("data"), detail::base64(detail::zlib_compress(volume_bytes)));
  const json& layers = j.at("layers");
  ASSERT_EQ(layers.at("cells").size(), 60u);
  for (std::size_t k = 0; k < 60; ++k) {
    EXPECT_EQ(layers.at("cells")[k], detail::base64(s.cells_zlib[k])) << k;
    EXPECT_EQ(layers.at("contours")[k][0].at("points"), b64_floats(s.contours[k][0].xy)) << k;
    EXPECT_EQ(layers.at("contours")[k][1].at("kind"), "hole") << k;
    EXPECT_EQ(layers.at("hatches")[k], b64_floats(s.hatches[k])) << k;
  }
  EXPECT_EQ(layers.at("stored"), json(s.stored));
}

TEST(WriteViewPage, WritesNothingWhenTheDataIsRefused) {
  test::TempDir dir("view-page");
  ViewPage page;
  page.source_path = "ring.stl";
  page.report_json = "not json";
  const Result<void> written = write_view_page(dir / "page.html", page);
  ASSERT_FALSE(written.has_value());
  EXPECT_EQ(written.error().to_string(), "ring.stl: the slice report is not JSON");
  EXPECT_FALSE(std::filesystem::exists(dir / "page.html"));
}

TEST(WriteViewPageData, WritesTheDataAloneOrNothingWhenItIsRefusedOrCannotBeWritten) {
  test::TempDir dir("view-page");
  ViewPage page;
  page.title = "probe-5e2b";
  page.stack = two_layer_stack(true);
  ASSERT_TRUE(write_view_page_data(dir / "view.json", page).has_value());
  EXPECT_EQ(test::read_file(dir / "view.json"), *view_page_data(page));
  page.validation_json = "{";
  const Result<void> refused = write_view_page_data(dir / "refused.json", page);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().message, "the validation report is not JSON");
  EXPECT_FALSE(std::filesystem::exists(dir / "refused.json"));
  page.validation_json.clear();
  std::filesystem::create_directory(dir / "taken.json");
  const Result<void> unwritable = write_view_page_data(dir / "taken.json", page);
  ASSERT_FALSE(unwritable.has_value());
  EXPECT_EQ(
      unwritable.error().to_string(),
      (dir / "taken.json").string() + ": cannot write the file: a folder of that name exists");
}

TEST(WriteViewPage, NamesAPathItCannotWrite) {
  test::TempDir dir("view-page");
  std::filesystem::create_directory(dir / "page.html");
  const Result<void> written = write_view_page(dir / "page.html", ViewPage{});
  ASSERT_FALSE(written.has_value());
  EXPECT_EQ(written.error().code, ErrorCode::BadInput);
  EXPECT_EQ(written.error().to_string(),
            (dir / "page.html").string() + ": cannot write the file: a folder of that name exists");
}

}  // namespace
}  // namespace strata::view
