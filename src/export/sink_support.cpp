#include <algorithm>
#include <charconv>
#include <system_error>
#include <utility>

#include "export/sink_support_internal.hpp"

namespace strata::io::detail {

namespace {

Error internal_error(const char* kind, std::string message) {
  return Error{ErrorCode::Internal, fmt::format("{}: {}", kind, message), {}};
}

/// Whether a layer handed to prepare_layer is one a writer can read: the engine's layers are,
/// and one that is not is left to add_layer's checks, which report it.
bool fits_grid(const LayerResult& layer, bool needs_cells, const GridSpec& grid) {
  return !needs_cells || layer.cells.size() == grid.cells_per_layer();
}

template <typename Write>
std::unique_ptr<PreparedLayer> encode_ahead(const LayerResult& layer, Write&& write) {
  auto encoded = std::make_unique<EncodedLayer>(layer.layer, Result<void>{});
  LayerBytes out{encoded->bytes};
  encoded->encoded = write(out);
  return encoded;
}

/// What prepare_layer made of `layer`, or null when it made nothing of it.
const EncodedLayer* encoded_for(const LayerResult& layer, const PreparedLayer* prepared) {
  const auto* encoded = dynamic_cast<const EncodedLayer*>(prepared);
  return encoded != nullptr && encoded->layer == layer.layer ? encoded : nullptr;
}

}  // namespace

Result<void> CreatedPaths::ensure_directory(const std::filesystem::path& dir) {
  if (dir.empty()) return {};
  std::error_code ec;
  std::vector<std::filesystem::path> missing;
  for (std::filesystem::path p = dir; !p.empty(); p = p.parent_path()) {
    const auto status = std::filesystem::status(p, ec);
    if (std::filesystem::exists(status)) {
      if (!std::filesystem::is_directory(status)) {
        return Error{ErrorCode::BadInput,
                     "cannot create the output folder: a file of that name exists", p.string()};
      }
      break;
    }
    missing.push_back(p);
    if (p == p.parent_path()) break;  // a root that does not exist
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!std::filesystem::create_directory(*it, ec)) {
      if (ec) {
        return Error{ErrorCode::BadInput,
                     fmt::format("cannot create the output folder: {}", ec.message()),
                     it->string()};
      }
      continue;  // created meanwhile by someone else: not ours to remove
    }
    dirs_.push_back(*it);
  }
  return {};
}

void CreatedPaths::remove_all() noexcept {
  std::error_code ec;
  for (const auto& file : files_) std::filesystem::remove(file, ec);
  files_.clear();
  // std::filesystem::remove deletes a folder only when it is empty, which is what we want:
  // a folder that meanwhile received files that are not ours stays.
  for (auto it = dirs_.rbegin(); it != dirs_.rend(); ++it) std::filesystem::remove(*it, ec);
  dirs_.clear();
}

Result<void> SinkProgress::check_begin(const char* sink) const {
  if (state_ != State::Idle) return internal_error(sink, "begin() called twice");
  return {};
}

Result<void> SinkProgress::check_layer(const LayerResult& layer, bool needs_cells,
                                       const char* sink) const {
  if (state_ != State::Started) {
    return internal_error(sink, "add_layer() outside begin() .. finish()");
  }
  if (layer.layer != next_layer_) {
    return internal_error(
        sink, fmt::format("layer {} arrived, expected layer {}", layer.layer, next_layer_));
  }
  if (layer.layer >= run_.grid.nz) {
    return internal_error(
        sink, fmt::format("layer {} is beyond the grid's {} layers", layer.layer, run_.grid.nz));
  }
  if (needs_cells && layer.cells.size() != run_.grid.cells_per_layer()) {
    return internal_error(sink, fmt::format("layer {} has {} cells, the grid {} x {} needs {}",
                                            layer.layer, layer.cells.size(), run_.grid.nx,
                                            run_.grid.ny, run_.grid.cells_per_layer()));
  }
  return {};
}

Result<void> SinkProgress::check_complete(const char* sink) const {
  if (state_ != State::Started) return internal_error(sink, "finish() without begin()");
  const LayerSpan span = run_.span();
  if (next_layer_ != span.end) {
    return internal_error(sink, fmt::format("finish() after {} of {} layers",
                                            next_layer_ - span.first, span.count()));
  }
  return {};
}

// ---------------------------------------------------------------------------------------------

SingleFileSink::SingleFileSink(std::filesystem::path path, const char* kind)
    : path_(std::move(path)), kind_(kind) {}

SingleFileSink::~SingleFileSink() {
  if (progress_.state() == SinkProgress::State::Started) abort();
}

Result<void> SingleFileSink::begin(const SliceRunInfo& run) {
  if (auto ok = progress_.check_begin(kind_); !ok) return ok;
  progress_.start(run);
  if (auto ok = created_.ensure_directory(path_.parent_path()); !ok) return ok;
  auto out = OutputFile::create(path_);
  if (!out) return out.error();
  out_ = std::move(out.value());
  return write_header(out_);
}

Result<void> SingleFileSink::add_layer(const LayerResult& layer) {
  return add_prepared_layer(layer, nullptr);
}

std::unique_ptr<PreparedLayer> SingleFileSink::prepare_layer(const LayerResult& layer) const {
  if (!encodes_ahead() || !fits_grid(layer, needs_cells(), progress_.grid())) return nullptr;
  return encode_ahead(layer, [&](LayerBytes& out) { return write_layer(out, layer); });
}

Result<void> SingleFileSink::add_prepared_layer(const LayerResult& layer,
                                                std::unique_ptr<PreparedLayer> prepared) {
  if (auto ok = progress_.check_layer(layer, needs_cells(), kind_); !ok) return ok;
  if (const EncodedLayer* encoded = encoded_for(layer, prepared.get())) {
    if (!encoded->encoded) return encoded->encoded;
    out_.write(encoded->bytes);
  } else {
    LayerBytes out{out_};
    if (auto ok = write_layer(out, layer); !ok) return ok;
  }
  progress_.layer_done();
  return {};
}

Result<void> SingleFileSink::finish() {
  if (auto ok = progress_.check_complete(kind_); !ok) return ok;
  if (auto ok = write_trailer(out_); !ok) return ok;
  if (auto ok = out_.commit(); !ok) return ok;
  created_.add_file(path_);
  progress_.set_state(SinkProgress::State::Finished);
  return {};
}

void SingleFileSink::abort() noexcept {
  out_.discard();
  created_.remove_all();
  progress_.set_state(SinkProgress::State::Aborted);
}

// ---------------------------------------------------------------------------------------------

LayerFilesSink::LayerFilesSink(const std::filesystem::path& dir, const char* subdir,
                               std::string stem, const char* extension, const char* kind)
    : folder_(dir / subdir), stem_(std::move(stem)), extension_(extension), kind_(kind) {}

LayerFilesSink::~LayerFilesSink() {
  if (progress_.state() == SinkProgress::State::Started) abort();
}

Result<void> LayerFilesSink::begin(const SliceRunInfo& run) {
  if (auto ok = progress_.check_begin(kind_); !ok) return ok;
  progress_.start(run);
  if (stem_.empty() || stem_.find_first_of("/\\") != std::string::npos) {
    return Error{
        ErrorCode::Usage,
        fmt::format("{}: the file stem '{}' must be a plain, non-empty name", kind_, stem_),
        folder_.string()};
  }
  return created_.ensure_directory(folder_);
}

Result<void> LayerFilesSink::add_layer(const LayerResult& layer) {
  return add_prepared_layer(layer, nullptr);
}

std::unique_ptr<PreparedLayer> LayerFilesSink::prepare_layer(const LayerResult& layer) const {
  if (!fits_grid(layer, needs_cells(), progress_.grid())) return nullptr;
  return encode_ahead(layer, [&](LayerBytes& out) { return write_layer(out, layer); });
}

Result<void> LayerFilesSink::add_prepared_layer(const LayerResult& layer,
                                                std::unique_ptr<PreparedLayer> prepared) {
  if (auto ok = progress_.check_layer(layer, needs_cells(), kind_); !ok) return ok;
  const EncodedLayer* encoded = encoded_for(layer, prepared.get());
  if (encoded != nullptr && !encoded->encoded) return encoded->encoded;
  const auto path = layer_path(layer.layer);
  auto out = OutputFile::create(path);
  if (!out) return out.error();
  if (encoded != nullptr) {
    out->write(encoded->bytes);
  } else {
    LayerBytes bytes{*out};
    if (auto ok = write_layer(bytes, layer); !ok) return ok;  // ~OutputFile removes the temporary
  }
  if (auto ok = out->commit(); !ok) return ok;
  created_.add_file(path);
  progress_.layer_done();
  return {};
}

Result<void> LayerFilesSink::finish() {
  if (auto ok = progress_.check_complete(kind_); !ok) return ok;
  remove_stale_layers();
  progress_.set_state(SinkProgress::State::Finished);
  return {};
}

void LayerFilesSink::abort() noexcept {
  created_.remove_all();
  progress_.set_state(SinkProgress::State::Aborted);
}

void LayerFilesSink::remove_stale_layers() noexcept {
  try {
    const std::string prefix = stem_ + "_";
    const std::string suffix = std::string(".") + extension_;
    const std::uint64_t nz = progress_.grid().nz;
    std::error_code ec;
    std::vector<std::filesystem::path> stale;
    for (std::filesystem::directory_iterator it(folder_, ec), end; !ec && it != end;
         it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() < prefix.size() + suffix.size() + 5) continue;
      if (name.compare(0, prefix.size(), prefix) != 0) continue;
      if (name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
      const char* first = name.data() + prefix.size();
      const char* last = name.data() + name.size() - suffix.size();
      if (!std::all_of(first, last, [](char c) { return c >= '0' && c <= '9'; })) continue;
      std::uint64_t index = 0;
      const auto parsed = std::from_chars(first, last, index);
      // An index too long for 64 bits is certainly beyond nz.
      if (parsed.ec == std::errc{} && index < nz) continue;
      stale.push_back(it->path());
    }
    for (const auto& path : stale) std::filesystem::remove(path, ec);
  } catch (...) {
    // Clean-up of an earlier run's files is best effort; this run's output is complete.
  }
}

}  // namespace strata::io::detail
