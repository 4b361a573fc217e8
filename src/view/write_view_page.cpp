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

/// Long base64 values kept out of the JSON document while it is written: each stands in it as a
/// marker until its text replaces it. Base64 needs no escape, and the JSON library would look
/// at each of its characters again (the display mesh of a large model is megabytes of it).
class HeldTexts {
 public:
  /// The marker to put in the document for `text`.
  std::string hold(std::string text) {
    std::string marker = fmt::format("\x01strata-held-{}\x01", texts_.size());
    // As a value it follows its key's colon: a name holding the marker's text has its quotes
    // escaped, and never matches.
    patterns_.push_back(std::string(":").append(json(marker).dump()));
    texts_.push_back(std::move(text));
    return marker;
  }

  /// `document` with every held text, in quotes, where its marker is.
  std::string put_back(std::string document) const {
    if (texts_.empty()) return document;
    std::vector<std::pair<std::size_t, std::size_t>> found;  // (where, which)
    std::size_t size = document.size();
    for (std::size_t k = 0; k < texts_.size(); ++k) {
      const std::size_t at = document.find(patterns_[k]);
      STRATA_ASSERT(at != std::string::npos, "a held text's marker is in the page data");
      found.emplace_back(at, k);
      size += texts_[k].size() + 3 - patterns_[k].size();
    }
    std::sort(found.begin(), found.end());
    std::string out;
    out.reserve(size);
    std::size_t from = 0;
    for (const auto& [at, k] : found) {
      out.append(document, from, at - from);
      out.append(":\"").append(texts_[k]).push_back('"');
      from = at + patterns_[k].size();
    }
    out.append(document, from);
    return out;
  }

 private:
  std::vector<std::string> patterns_;
  std::vector<std::string> texts_;
};

/// The text of a base64 string of `bytes`, with its quotes, at `to`; returns the end.
char* write_quoted_base64(std::string_view bytes, char* to) {
  *to++ = '"';
  to = detail::write_base64(bytes, to);
  *to++ = '"';
  return to;
}

constexpr std::string_view kKindKey = R"({"kind":")";
constexpr std::string_view kPointsKey = R"(","points":")";

/// Characters of a layer's contours as the page reads them:
/// [{"kind":"outer","points":"<base64 of x, y floats>"},...]
std::size_t contours_size(const std::vector<ViewLoop>& loops) {
  std::size_t size = 2 + (loops.empty() ? 0 : loops.size() - 1);
  for (const ViewLoop& loop : loops) {
    size += kKindKey.size() + std::string_view(loop_kind_name(loop.kind)).size() +
            kPointsKey.size() + detail::base64_size(sizeof(float) * loop.xy.size()) + 2;
  }
  return size;
}

/// Writes the contours_size(loops) characters of a layer's contours at `to`; returns the end.
char* write_contours(const std::vector<ViewLoop>& loops, char* to) {
  const auto put = [&](std::string_view text) { to = std::copy(text.begin(), text.end(), to); };
  *to++ = '[';
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (l > 0) *to++ = ',';
    put(kKindKey);
    put(loop_kind_name(loops[l].kind));
    put(kPointsKey);
    to = detail::write_base64(detail::as_bytes(loops[l].xy), to);
    put("\"}");
  }
  *to++ = ']';
  return to;
}

/// The page's data with the layers' text where their marker stood, between `before` and
/// `after`, the rest of the document. The "layers" object is compact JSON, keys in the order the
/// JSON library writes them (sorted); base64 and the loop kinds need no escaping. Each layer is
/// written in parallel straight to its place in the one string of the page's size: the layers are
/// most of a page (tens of MB), which a string a layer, then an array, then the document would
/// hold three times over and copy as often.
std::string with_layers_text(std::string_view before, const ViewStack& s, std::string_view after) {
  const std::size_t n = s.stored.size();
  std::vector<std::size_t> cells_at(n + 1), contours_at(n + 1), hatches_at(n + 1);
  // Item k of an array starts at at[k] (its comma before it); at[n] is the array's "]".
  const auto lay_out = [&](std::vector<std::size_t>& at, std::size_t start, auto item_size) {
    at[0] = start + 1;
    for (std::size_t k = 0; k < n; ++k) at[k + 1] = at[k] + (k > 0) + item_size(k);
    return at[n] + 1;
  };
  const std::string_view cells_key = R"({"cells":)";
  const std::string_view contours_key = R"(,"contours":)";
  const std::string_view hatches_key = R"(,"encoding":"2bit-msb-zlib","hatches":)";
  const std::string tail =
      R"(,"stored":)" + json(s.stored).dump() + fmt::format(R"(,"stride":{}}})", s.stride);
  std::size_t end = lay_out(cells_at, before.size() + cells_key.size(), [&](std::size_t k) {
    return 2 + detail::base64_size(s.cells_zlib[k].size());
  });
  end = lay_out(contours_at, end + contours_key.size(),
                [&](std::size_t k) { return contours_size(s.contours[k]); });
  end += hatches_key.size();
  if (s.has_hatches) {
    end = lay_out(hatches_at, end, [&](std::size_t k) {
      return 2 + detail::base64_size(sizeof(float) * s.hatches[k].size());
    });
  } else {
    end += 4;  // null
  }
  const std::size_t layers_end = end + tail.size();

  std::string text(layers_end + after.size(), '\0');
  char* const base = text.data();
  const auto put = [](std::string_view piece, char* to) {
    return std::copy(piece.begin(), piece.end(), to);
  };
  put(cells_key, put(before, base));
  put(contours_key, base + cells_at[n] + 1);
  char* hatches = put(hatches_key, base + contours_at[n] + 1);
  if (s.has_hatches) {
    hatches[0] = '[';
    base[hatches_at[n]] = ']';
  } else {
    put("null", hatches);
  }
  base[cells_at[0] - 1] = '[';
  base[cells_at[n]] = ']';
  base[contours_at[0] - 1] = '[';
  base[contours_at[n]] = ']';
  put(after, put(tail, base + layers_end - tail.size()));
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
    const auto item = [&](const std::vector<std::size_t>& at) {
      char* to = base + at[k];
      if (k > 0) *to++ = ',';
      return to;
    };
    write_quoted_base64(s.cells_zlib[k], item(cells_at));
    write_contours(s.contours[k], item(contours_at));
    if (s.has_hatches) write_quoted_base64(detail::as_bytes(s.hatches[k]), item(hatches_at));
  });
  return text;
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

/// `text` with every "</" written "<\/": a script element ends at "</", and the JSON string
/// "<\/" reads the same.
std::string escape_script_end(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  std::size_t from = 0;
  for (std::size_t at = text.find("</"); at != std::string_view::npos;
       at = text.find("</", at + 1)) {
    escaped.append(text, from, at + 1 - from);
    escaped.push_back('\\');
    from = at + 1;
  }
  escaped.append(text, from);
  return escaped;
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
  HeldTexts held;
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
                    {"positions", held.hold(b64(m.positions))},
                    {"indices", held.hold(b64(m.indices))}};
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
                      {"data", held.hold(detail::base64(detail::zlib_compress(volume_bytes)))}};
  }

  data["validation"] = nullptr;
  if (!page.validation_json.empty()) {
    const json validation = json::parse(page.validation_json, nullptr, false);
    if (validation.is_discarded()) {
      return Error{ErrorCode::BadInput, "the validation report is not JSON", page.source_path};
    }
    data["validation"] = validation_view(validation);
  }

  // Invalid UTF-8 in a name (a path of the model) is replaced rather than refused. The document
  // is escaped for its script element while the long texts, base64 and the layers, which hold
  // no "<", are still their markers: once, over the rest of the document alone.
  const std::string text =
      held.put_back(escape_script_end(data.dump(-1, ' ', false, json::error_handler_t::replace)));
  // With its key: a name holding the marker's text is written with its quotes escaped.
  const std::string key = R"("layers":)";
  const std::string marker = key + json(kLayersMarker).dump();
  const std::size_t marker_at = text.find(marker);
  STRATA_ASSERT(marker_at != std::string::npos, "the layers' marker is in the page data");
  const std::string_view document = text;
  return with_layers_text(document.substr(0, marker_at + key.size()), page.stack,
                          document.substr(marker_at + marker.size()));
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
