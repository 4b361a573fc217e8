#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "strata/core/error.hpp"
#include "strata/io/output_file.hpp"
#include "strata/view/view_page.hpp"
#include "view/encode_internal.hpp"
#include "view/view_template_internal.hpp"

namespace strata::view {

namespace {

using nlohmann::json;

const char* loop_kind_name(LoopKind kind) {
  switch (kind) {
    case LoopKind::Outer:
      return "outer";
    case LoopKind::Hole:
      return "hole";
    case LoopKind::Open:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "open";
}

template <class T>
std::string b64(const std::vector<T>& values) {
  return detail::base64(detail::as_bytes(values));
}

/// Stands for the layers in the page's JSON until their text replaces it; control characters
/// make it a string no name or note can be.
constexpr const char* kLayersMarker = "\x01strata-layers\x01";

/// The page's "layers" object as compact JSON, keys in the order the JSON library writes them
/// (sorted). Base64 and the loop kinds need no escaping.
std::string layers_text(const ViewStack& s) {
  const std::size_t n = s.stored.size();
  std::vector<std::string> cells(n), contours(n), hatches(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
    cells[k] = '"' + detail::base64(s.cells_zlib[k]) + '"';
    std::string& loops = contours[k];
    loops = "[";
    for (const ViewLoop& loop : s.contours[k]) {
      if (loops.size() > 1) loops += ',';
      loops += R"({"kind":")";
      loops += loop_kind_name(loop.kind);
      loops += R"(","points":")";
      loops += b64(loop.xy);
      loops += "\"}";
    }
    loops += ']';
    if (s.has_hatches) hatches[k] = '"' + b64(s.hatches[k]) + '"';
  });
  const auto array = [&](const std::vector<std::string>& items) {
    std::size_t size = 2 + n;
    for (const std::string& item : items) size += item.size();
    std::string out;
    out.reserve(size);
    out += '[';
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) out += ',';
      out += items[k];
    }
    out += ']';
    return out;
  };
  std::string out = R"({"cells":)";
  out += array(cells);
  out += R"(,"contours":)";
  out += array(contours);
  out += R"(,"encoding":"2bit-msb-zlib","hatches":)";
  out += s.has_hatches ? array(hatches) : std::string("null");
  out += R"(,"stored":)";
  out += json(s.stored).dump();
  out += fmt::format(R"(,"stride":{}}})", s.stride);
  return out;
}

void push_segment(std::vector<float>& out, const Vec3& a, const Vec3& b) {
  for (const Vec3& p : {a, b}) {
    out.insert(out.end(),
               {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  }
}

json defect(const char* kind, const char* label, std::size_t count, const char* shape,
            const std::vector<float>& data) {
  const std::size_t per = shape[0] == 's' ? 6 : shape[0] == 't' ? 9 : 3;
  return {{"kind", kind},   {"label", label},    {"count", count},
          {"shape", shape}, {"data", b64(data)}, {"shown", data.size() / per}};
}

json edges(const char* kind, const char* label,
           const diagnose::Occurrences<diagnose::EdgeLocation>& found) {
  std::vector<float> data;
  for (const auto& e : found.locations) push_segment(data, e.from, e.to);
  return defect(kind, label, found.count, "segments", data);
}

json facets(const char* kind, const char* label, const std::vector<FacetIndex>& which,
            std::size_t count, const IndexedMesh& mesh) {
  std::vector<float> data;
  for (FacetIndex f : which) {
    if (f >= mesh.triangles.size()) continue;
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = mesh.corner(f, c);
      data.insert(data.end(),
                  {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
  }
  return defect(kind, label, count, "triangles", data);
}

json check_json(const diagnose::MeshReport& r, const IndexedMesh* mesh) {
  json defects = json::array();
  const auto add_if = [&](json d) {
    if (d["count"].get<std::size_t>() > 0) defects.push_back(std::move(d));
  };
  add_if(edges("open_edges", "open edges", r.boundary_edges));
  add_if(edges("non_manifold_edges", "non-manifold edges", r.non_manifold_edges));
  add_if(edges("inconsistent_edges", "edges of flipped neighbours", r.inconsistent_edges));
  if (mesh != nullptr) {
    add_if(facets("degenerate_facets", "degenerate facets", r.degenerate_facets.locations,
                  r.degenerate_facets.count, *mesh));
    add_if(facets("flipped_normals", "facets against their stored normal",
                  r.flipped_normals.locations, r.flipped_normals.count, *mesh));
    std::vector<FacetIndex> pairs;
    for (const auto& p : r.self_intersections.locations) {
      pairs.push_back(p.first);
      pairs.push_back(p.second);
    }
    add_if(facets("self_intersections", "self-intersecting facets", pairs,
                  r.self_intersections.count, *mesh));
  }
  std::vector<float> points;
  for (const Vec3& v : r.non_manifold_vertices.locations) {
    points.insert(points.end(),
                  {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
  }
  add_if(defect("non_manifold_vertices", "non-manifold vertices", r.non_manifold_vertices.count,
                "points", points));
  return {{"verdict", diagnose::verdict_name(r.verdict)},
          {"reason", r.verdict_reason},
          {"self_intersections_checked", r.self_intersections_checked},
          {"facets", r.num_facets},
          {"shells", r.shells.size()},
          {"defects", defects}};
}

/// The validation report reduced to what the page marks: differing layers and cells.
json validation_view(const json& v) {
  json out = {{"cells_compared", 0}, {"cells_differing", 0}};
  const json& cells = v.contains("cells") ? v["cells"] : json::object();
  out["cells_compared"] = cells.value("compared", std::uint64_t{0});
  out["cells_differing"] = cells.value("differing", std::uint64_t{0});
  json listed = json::array();
  std::vector<std::uint32_t> layers;
  const auto code = [](const json& c) {
    const std::string s = c.is_string() ? c.get<std::string>() : "00";
    return s == "11" ? 3 : s == "01" ? 1 : 0;
  };
  if (cells.contains("differences") && cells["differences"].is_array()) {
    for (const json& d : cells["differences"]) {
      const auto k = d.value("k", 0U);
      listed.push_back({d.value("i", 0U), d.value("j", 0U), k, code(d.value("fast", json())),
                        code(d.value("exact", json()))});
      layers.push_back(k);
    }
  }
  std::sort(layers.begin(), layers.end());
  layers.erase(std::unique(layers.begin(), layers.end()), layers.end());
  out["layers_differing"] = layers;
  out["cells"] = listed;
  return out;
}

/// The viewer's text before and after its data marker.
struct TemplateParts {
  std::string_view before;
  std::string_view after;
};

TemplateParts template_parts() {
  const std::string_view page_template = detail::view_page_template();
  const std::size_t at = page_template.find(detail::kViewDataMarker);
  STRATA_ASSERT(at != std::string_view::npos, "the view template holds the data marker");
  return {page_template.substr(0, at), page_template.substr(at + detail::kViewDataMarker.size())};
}

}  // namespace

Result<std::string> view_page_data(const ViewPage& page) {
  json data;
  data["format"] = "strata-view";
  data["version"] = 1;
  data["title"] = page.title;
  data["generator"] = "strata 0.1.0";
  data["source"] = {{"kind", page.source_kind}, {"path", page.source_path}};
  std::vector<std::string> notes = page.notes;
  notes.insert(notes.end(), page.stack.notes.begin(), page.stack.notes.end());
  data["notes"] = notes;
  const GridSpec& g = page.stack.grid;
  data["grid"] = {{"nx", g.nx}, {"ny", g.ny}, {"nz", g.nz}, {"x0", g.x0}, {"y0", g.y0},
                  {"z0", g.z0}, {"dx", g.dx}, {"dy", g.dy}, {"dz", g.dz}};
  data["shell_mm"] = page.stack.shell_mm;

  data["report"] = nullptr;
  if (!page.report_json.empty()) {
    json report = json::parse(page.report_json, nullptr, false);
    if (report.is_discarded()) {
      return Error{ErrorCode::BadInput, "the slice report is not JSON", page.source_path};
    }
    data["report"] = std::move(report);
  }

  data["mesh"] = nullptr;
  if (page.mesh) {
    const DisplayMesh& m = *page.mesh;
    data["mesh"] = {{"facets_in_model", m.facets_in_model},
                    {"facets_shown", m.facets()},
                    {"simplified", m.simplified},
                    {"positions", b64(m.positions)},
                    {"indices", b64(m.indices)}};
  }
  data["check"] = nullptr;
  if (page.check) data["check"] = check_json(*page.check, page.model_mesh);

  // The layers are most of the page (tens of MB of base64): their text is written directly, in
  // parallel, where a JSON value's serialisation would look at every character again. A marker
  // string holds their place in the document; the text is what the JSON library would write.
  data["layers"] = kLayersMarker;
  // No volume when no layer was collected (a model checked, not sliced yet).
  data["volume"] = nullptr;
  if (const ViewVolume& v = page.stack.volume; !v.blocks.empty()) {
    const std::string_view volume_bytes(reinterpret_cast<const char*>(v.blocks.data()),
                                        v.blocks.size());
    data["volume"] = {{"nx", v.nx},
                      {"ny", v.ny},
                      {"nz", v.nz},
                      {"bx", v.bx},
                      {"by", v.by},
                      {"bz", v.bz},
                      {"data", detail::base64(detail::zlib_compress(volume_bytes))}};
  }

  data["validation"] = nullptr;
  if (!page.validation_json.empty()) {
    const json validation = json::parse(page.validation_json, nullptr, false);
    if (validation.is_discarded()) {
      return Error{ErrorCode::BadInput, "the validation report is not JSON", page.source_path};
    }
    data["validation"] = validation_view(validation);
  }

  // Invalid UTF-8 in a name (a path of the model) is replaced rather than refused.
  std::string text = data.dump(-1, ' ', false, json::error_handler_t::replace);
  // With its key: a name holding the marker's text is written with its quotes escaped.
  const std::string key = R"("layers":)";
  const std::string marker = key + json(kLayersMarker).dump();
  const std::size_t marker_at = text.find(marker);
  STRATA_ASSERT(marker_at != std::string::npos, "the layers' marker is in the page data");
  text.replace(marker_at + key.size(), marker.size() - key.size(), layers_text(page.stack));
  // A script element ends at "</": the JSON string "<\/" reads the same. Copied in pieces
  // between the few places that need it (tens of MB of layers have none).
  std::size_t at = text.find("</");
  if (at == std::string::npos) return text;
  std::string escaped;
  escaped.reserve(text.size() + 64);
  std::size_t from = 0;
  for (; at != std::string::npos; at = text.find("</", at + 1)) {
    escaped.append(text, from, at + 1 - from);
    escaped.push_back('\\');
    from = at + 1;
  }
  escaped.append(text, from);
  return escaped;
}

std::string view_page_with_data(std::string_view data) {
  const TemplateParts parts = template_parts();
  std::string page;
  page.reserve(parts.before.size() + data.size() + parts.after.size());
  page.append(parts.before);
  page.append(data);
  page.append(parts.after);
  return page;
}

Result<void> write_view_page(const std::filesystem::path& path, const ViewPage& page) {
  auto data = view_page_data(page);
  if (!data) return data.error();
  const TemplateParts parts = template_parts();
  // Written in three pieces: the data of a large stack is not copied into a page string.
  auto out = io::OutputFile::create(path);
  if (!out) return out.error();
  out->write(parts.before);
  out->write(*data);
  out->write(parts.after);
  return out->commit();
}

}  // namespace strata::view
