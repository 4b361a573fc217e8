#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <deque>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

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

/// Where the page's data goes, a piece at a time: the page file, or a string.
using TextSink = std::function<void(std::string_view)>;

/// Raw bytes base64-encoded per piece, so that no whole copy of a long text is held: a multiple of
/// 3 bytes, whose encodings join into the encoding of the whole.
constexpr std::size_t kBase64PieceBytes = 3 * 64 * 1024;
/// The layers' text is made in parallel a batch of about this many characters at a time.
constexpr std::size_t kLayersBatchChars = std::size_t{1} << 20;

void write_base64_pieces(std::string_view bytes, std::string& buffer, const TextSink& sink) {
  for (std::size_t from = 0; from < bytes.size(); from += kBase64PieceBytes) {
    const std::string_view piece = bytes.substr(from, kBase64PieceBytes);
    buffer.resize(detail::base64_size(piece.size()));
    detail::write_base64(piece, buffer.data());
    sink(buffer);
  }
}

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

/// The "layers" object of the page's data: compact JSON, keys in the order the JSON library writes
/// them (sorted), what it would write for the same values; base64 and the loop kinds need no
/// escaping. The layers are most of a page (tens of MB): their text is made a batch of layers at
/// a time, each layer in parallel straight to its place in the batch, and handed on, rather than
/// held whole (or, through JSON values, three times over).
class LayersText {
 public:
  explicit LayersText(const ViewStack& stack)
      : s_(stack),
        tail_(R"(,"stored":)" + json(s_.stored).dump() +
              fmt::format(R"(,"stride":{}}})", s_.stride)) {}

  std::size_t size() const {
    std::size_t size = kCellsKey.size() + kContoursKey.size() + kHatchesKey.size() + tail_.size();
    size += array_size([&](std::size_t k) { return cells_size(k); });
    size += array_size([&](std::size_t k) { return contours_size(s_.contours[k]); });
    size += s_.has_hatches ? array_size([&](std::size_t k) { return hatches_size(k); }) : 4;
    return size;
  }

  void write(const TextSink& sink) const {
    std::string batch;
    sink(kCellsKey);
    write_array([&](std::size_t k) { return cells_size(k); },
                [&](std::size_t k, char* to) { write_quoted_base64(s_.cells_zlib[k], to); }, batch,
                sink);
    sink(kContoursKey);
    write_array([&](std::size_t k) { return contours_size(s_.contours[k]); },
                [&](std::size_t k, char* to) { write_contours(s_.contours[k], to); }, batch, sink);
    sink(kHatchesKey);
    if (s_.has_hatches) {
      write_array([&](std::size_t k) { return hatches_size(k); },
                  [&](std::size_t k, char* to) {
                    write_quoted_base64(detail::as_bytes(s_.hatches[k]), to);
                  },
                  batch, sink);
    } else {
      sink("null");
    }
    sink(tail_);
  }

 private:
  static constexpr std::string_view kCellsKey = R"({"cells":)";
  static constexpr std::string_view kContoursKey = R"(,"contours":)";
  static constexpr std::string_view kHatchesKey = R"(,"encoding":"2bit-msb-zlib","hatches":)";

  std::size_t cells_size(std::size_t k) const {
    return 2 + detail::base64_size(s_.cells_zlib[k].size());
  }
  std::size_t hatches_size(std::size_t k) const {
    return 2 + detail::base64_size(sizeof(float) * s_.hatches[k].size());
  }
  std::size_t layers() const { return s_.stored.size(); }

  /// Characters of an array of one item a layer: "[", the items with a comma between, "]".
  template <class ItemSize>
  std::size_t array_size(ItemSize item_size) const {
    std::size_t size = 2 + (layers() > 0 ? layers() - 1 : 0);
    for (std::size_t k = 0; k < layers(); ++k) size += item_size(k);
    return size;
  }

  template <class ItemSize, class WriteItem>
  void write_array(ItemSize item_size, WriteItem write_item, std::string& batch,
                   const TextSink& sink) const {
    sink("[");
    std::vector<std::size_t> at;  // where each item of the batch starts, its comma before it
    for (std::size_t first = 0; first < layers();) {
      at.clear();
      std::size_t chars = 0;
      std::size_t end = first;
      for (; end < layers() && (end == first || chars < kLayersBatchChars); ++end) {
        at.push_back(chars);
        chars += (end > 0) + item_size(end);
      }
      batch.resize(chars);
      tbb::parallel_for(first, end, [&](std::size_t k) {
        char* to = batch.data() + at[k - first];
        if (k > 0) *to++ = ',';
        write_item(k, to);
      });
      sink(batch);
      first = end;
    }
    sink("]");
  }

  const ViewStack& s_;
  std::string tail_;
};

/// The page's data as a JSON document in which long texts stand as markers: the layers, and base64
/// values (the display mesh of a large model is megabytes of it), which the JSON library would
/// look at a character at a time again. A marker is a string of control characters, found with
/// its key's colon (the layers' with its key) before it, and replaced as the document is handed
/// on. A name or note may hold the same text (a file name may hold control characters): the
/// markers carry a salt, and a document in which a marker does not stand exactly once is
/// composed again with the next salt.
class MarkedDocument {
 public:
  explicit MarkedDocument(std::uint32_t salt) : salt_(salt) {}
  // Its held texts point into what it keeps, and at the layers' text it holds.
  MarkedDocument(const MarkedDocument&) = delete;
  MarkedDocument& operator=(const MarkedDocument&) = delete;

  /// The marker to put in the document for the base64 text of `bytes`, which must outlive this.
  std::string hold_base64(std::string_view bytes) {
    std::string marker = fmt::format("\x01strata-held-{}-{}\x01", salt_, held_.size());
    held_.push_back({std::string(":").append(json(marker).dump()), ":\"", bytes, nullptr});
    return marker;
  }
  /// The same for bytes this keeps.
  std::string keep_base64(std::string bytes) {
    kept_.push_back(std::move(bytes));
    return hold_base64(std::string_view(kept_.back()));
  }
  /// The marker to put in the document for the "layers" object of `stack`. Once: a document
  /// has one "layers".
  std::string hold_layers(const ViewStack& stack) {
    STRATA_ASSERT(!layers_, "a page's data holds its layers once");
    layers_.emplace(stack);
    std::string marker = fmt::format("\x01strata-layers-{}\x01", salt_);
    held_.push_back(
        {std::string(R"("layers":)").append(json(marker).dump()), R"("layers":)", {}, &*layers_});
    return marker;
  }

  /// Takes the document the markers were put in; false when a marker does not stand in it
  /// exactly once (a name or note holds its text), and the document must be composed again.
  [[nodiscard]] bool set_document(std::string document) {
    document_ = std::move(document);
    found_.clear();
    for (std::size_t k = 0; k < held_.size(); ++k) {
      const std::size_t at = document_.find(held_[k].pattern);
      STRATA_ASSERT(at != std::string::npos, "a held text's marker is in the page data");
      if (document_.find(held_[k].pattern, at + 1) != std::string::npos) return false;
      found_.emplace_back(at, k);
    }
    std::sort(found_.begin(), found_.end());
    return true;
  }

  /// Characters of the document with every held text in place.
  std::size_t size() const {
    std::size_t size = document_.size();
    for (const Held& h : held_) {
      size += h.opening.size() - h.pattern.size() +
              (h.layers != nullptr ? h.layers->size() : detail::base64_size(h.bytes.size()) + 1);
    }
    return size;
  }

  void write(const TextSink& sink) const {
    const std::string_view document = document_;
    std::string buffer;
    std::size_t from = 0;
    for (const auto& [at, k] : found_) {
      const Held& h = held_[k];
      sink(document.substr(from, at - from));
      sink(h.opening);
      if (h.layers != nullptr) {
        h.layers->write(sink);
      } else {
        write_base64_pieces(h.bytes, buffer, sink);
        sink("\"");
      }
      from = at + h.pattern.size();
    }
    sink(document.substr(from));
  }

 private:
  struct Held {
    std::string pattern;       ///< the marker as it stands in the document, with its colon
    std::string_view opening;  ///< what the text follows in its place
    std::string_view bytes;    ///< to be written as a base64 string, when not the layers
    const LayersText* layers;
  };
  std::uint32_t salt_;
  std::string document_;
  std::vector<Held> held_;
  std::vector<std::pair<std::size_t, std::size_t>> found_;  // (where, which), in order
  std::deque<std::string> kept_;
  std::optional<LayersText> layers_;
};

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

/// The page's data as a marked document in `out` (which the page must outlive); false when a
/// marker of `out` does not stand once in it (MarkedDocument::set_document).
Result<bool> compose_page_data(const ViewPage& page, MarkedDocument& out) {
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
                    {"positions", out.hold_base64(detail::as_bytes(m.positions))},
                    {"indices", out.hold_base64(detail::as_bytes(m.indices))}};
  }
  data["check"] = nullptr;
  if (page.check) data["check"] = check_json(*page.check, page.model_mesh);

  data["layers"] = out.hold_layers(page.stack);
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
                      {"data", out.keep_base64(detail::zlib_compress(volume_bytes))}};
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
  return out.set_document(
      escape_script_end(data.dump(-1, ' ', false, json::error_handler_t::replace)));
}

/// The page's data as a marked document whose markers each stand once in it. A salt that a name
/// or note collides with is passed by; the document's strings are few, so some salt is free.
Result<std::unique_ptr<MarkedDocument>> page_document(const ViewPage& page) {
  for (std::uint32_t salt = 0;; ++salt) {
    auto document = std::make_unique<MarkedDocument>(salt);
    const Result<bool> composed = compose_page_data(page, *document);
    if (!composed) return composed.error();
    if (*composed) return document;
  }
}

}  // namespace

Result<std::string> view_page_data(const ViewPage& page) {
  auto document = page_document(page);
  if (!document) return document.error();
  std::string text;
  text.reserve((*document)->size());
  (*document)->write([&](std::string_view piece) { text.append(piece); });
  return text;
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

namespace {

/// Writes `before`, the page's data and `after` to `path` atomically, a piece at a time: the
/// data of a large stack is never held whole.
Result<void> write_data_between(const std::filesystem::path& path, const ViewPage& page,
                                std::string_view before, std::string_view after) {
  auto document = page_document(page);
  if (!document) return document.error();
  auto out = io::OutputFile::create(path);
  if (!out) return out.error();
  out->write(before);
  (*document)->write([&](std::string_view piece) { out->write(piece); });
  out->write(after);
  return out->commit();
}

}  // namespace

Result<void> write_view_page_data(const std::filesystem::path& path, const ViewPage& page) {
  return write_data_between(path, page, {}, {});
}

Result<void> write_view_page(const std::filesystem::path& path, const ViewPage& page) {
  const TemplateParts parts = template_parts();
  return write_data_between(path, page, parts.before, parts.after);
}

}  // namespace strata::view
