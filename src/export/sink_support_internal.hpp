#pragma once

// Pieces shared by the layer writers of src/export/: the paths a sink created (so abort() can take
// them away), the order checks every sink makes, little-endian encoding, number formatting.

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "export/shortest_number_internal.hpp"
#include "io/little_endian.hpp"
#include "strata/core/result.hpp"
#include "strata/io/output_file.hpp"
#include "strata/pipeline/layer_sink.hpp"

namespace strata::io::detail {

/// `<stem>_<index, 5 digits at least>.<extension>`: the name of a layer file.
inline std::string layer_file_name(const std::string& stem, std::uint32_t k,
                                   const char* extension) {
  return fmt::format("{}_{:05}.{}", stem, k, extension);
}

/// The folders and finished files a sink created, so that abort() can remove them again.
class CreatedPaths {
 public:
  /// Creates `dir` and its missing parents, remembering each folder it created.
  Result<void> ensure_directory(const std::filesystem::path& dir);
  /// Remembers a finished file.
  void add_file(const std::filesystem::path& file) { files_.push_back(file); }
  /// Removes the remembered files, then the remembered folders (deepest first) that are empty.
  void remove_all() noexcept;

 private:
  std::vector<std::filesystem::path> files_;
  std::vector<std::filesystem::path> dirs_;  ///< in creation order, parents first
};

/// Where a sink is in its life: begin, the layers of the run's span in order, finish or abort.
class SinkProgress {
 public:
  enum class State { Idle, Started, Finished, Aborted };

  void start(const SliceRunInfo& run) {
    run_ = run;
    next_layer_ = run.span().first;
    state_ = State::Started;
  }
  /// Checks that `layer` is the next one and, if `needs_cells`, that it carries nx * ny cells.
  Result<void> check_layer(const LayerResult& layer, bool needs_cells, const char* sink) const;
  void layer_done() { ++next_layer_; }
  /// Checks that every layer of the span arrived.
  Result<void> check_complete(const char* sink) const;
  Result<void> check_begin(const char* sink) const;

  const SliceRunInfo& run() const { return run_; }
  const GridSpec& grid() const { return run_.grid; }
  State state() const { return state_; }
  void set_state(State state) { state_ = state; }

 private:
  SliceRunInfo run_;
  std::uint32_t next_layer_ = 0;
  State state_ = State::Idle;
};

/// Where a writer puts a layer's bytes: straight into the file, or into memory when the layer is
/// encoded ahead on a worker thread (LayerSink::prepare_layer).
class LayerBytes {
 public:
  explicit LayerBytes(OutputFile& file) : file_(&file) {}
  explicit LayerBytes(std::string& memory) : memory_(&memory) {}
  /// Room for `bytes` more in memory, so that appending them moves nothing already written; a
  /// file needs none.
  void reserve_more(std::size_t bytes) {
    if (memory_ != nullptr) memory_->reserve(memory_->size() + bytes);
  }
  /// The memory the bytes go to, or null when they go to a file: a writer may then encode
  /// straight into it rather than through a buffer of its own.
  std::string* memory() const { return memory_; }
  void write(std::string_view bytes) {
    if (file_ != nullptr) {
      file_->write(bytes);
    } else {
      memory_->append(bytes);
    }
  }

 private:
  OutputFile* file_ = nullptr;
  std::string* memory_ = nullptr;
};

/// A layer's bytes, encoded ahead by a writer's prepare_layer.
struct EncodedLayer final : PreparedLayer {
  EncodedLayer(std::uint32_t k, Result<void> status) : layer(k), encoded(std::move(status)) {}
  std::uint32_t layer;
  Result<void> encoded;  ///< the writer's error, reported when the layer's turn comes
  std::string bytes;
};

/// Base of the sinks that write one file: begin() opens it under a temporary name and writes the
/// header, add_layer() appends, finish() writes the trailer and renames the file into place.
class SingleFileSink : public LayerSink {
 public:
  /// `kind` names the sink in messages ("cells writer").
  SingleFileSink(std::filesystem::path path, const char* kind);
  ~SingleFileSink() override;
  SingleFileSink(const SingleFileSink&) = delete;
  SingleFileSink& operator=(const SingleFileSink&) = delete;

  Result<void> begin(const SliceRunInfo& run) final;
  Result<void> add_layer(const LayerResult& layer) final;
  std::unique_ptr<PreparedLayer> prepare_layer(const LayerResult& layer) const final;
  Result<void> add_prepared_layer(const LayerResult& layer,
                                  std::unique_ptr<PreparedLayer> prepared) final;
  Result<void> finish() final;
  void abort() noexcept final;
  bool needs_cells() const override = 0;

 protected:
  virtual Result<void> write_header(OutputFile& out) = 0;
  /// Writes one layer's bytes; const, reading only run(), since it may run on a worker thread.
  virtual Result<void> write_layer(LayerBytes& out, const LayerResult& layer) const = 0;
  /// Whether a layer's bytes may be held in memory to be encoded ahead; a writer whose layers
  /// can be far larger than their cells says no and streams them.
  virtual bool encodes_ahead() const { return true; }
  virtual Result<void> write_trailer(OutputFile& out) { return {}; }
  const SliceRunInfo& run() const { return progress_.run(); }

 private:
  std::filesystem::path path_;
  const char* kind_;
  SinkProgress progress_;
  CreatedPaths created_;
  OutputFile out_;
};

/// Base of the sinks that write a file a layer into `dir/<subdir>/<stem>_<k>.<extension>`; each
/// file is renamed into place as soon as it is complete, and remembered so abort() can remove it.
class LayerFilesSink : public LayerSink {
 public:
  LayerFilesSink(const std::filesystem::path& dir, const char* subdir, std::string stem,
                 const char* extension, const char* kind);
  ~LayerFilesSink() override;
  LayerFilesSink(const LayerFilesSink&) = delete;
  LayerFilesSink& operator=(const LayerFilesSink&) = delete;

  Result<void> begin(const SliceRunInfo& run) final;
  Result<void> add_layer(const LayerResult& layer) final;
  std::unique_ptr<PreparedLayer> prepare_layer(const LayerResult& layer) const final;
  Result<void> add_prepared_layer(const LayerResult& layer,
                                  std::unique_ptr<PreparedLayer> prepared) final;
  Result<void> finish() final;
  void abort() noexcept final;
  bool needs_cells() const override = 0;

 protected:
  /// Writes one layer's file; const, reading only run(), since it may run on a worker thread.
  virtual Result<void> write_layer(LayerBytes& out, const LayerResult& layer) const = 0;
  const SliceRunInfo& run() const { return progress_.run(); }
  const std::string& stem() const { return stem_; }
  /// The file of layer k.
  std::filesystem::path layer_path(std::uint32_t k) const {
    return folder_ / layer_file_name(stem_, k, extension_);
  }

 private:
  /// Removes `<stem>_<index>.<extension>` files with index >= nz left by an earlier run.
  void remove_stale_layers() noexcept;

  std::filesystem::path folder_;
  std::string stem_;
  const char* extension_;
  const char* kind_;
  SinkProgress progress_;
  CreatedPaths created_;
};

/// Appends a double in the shortest form that reads back to the same bits.
inline void append_number(std::string& out, double v) {
  // Written to the stack, then appended: the string is not grown a character at a time.
  char digits[kShortestNumberChars];
  out.append(digits, write_shortest(digits, v));
}

/// A number written many times in a row (a scanline's y, once or twice for each of its row's
/// hatches), formatted once for as long as it stays the same: the same text as append_number.
class RepeatedNumber {
 public:
  /// Writes the text at `out` as write_shortest does (with as much room after it); returns the
  /// end. A copy of constant length, which the compiler makes a few moves: the text is shorter.
  char* write(char* out, double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    if (length_ == 0 || bits != bits_) {
      bits_ = bits;
      length_ = static_cast<std::size_t>(write_shortest(digits_, v) - digits_);
    }
    static_assert(kShortestNumberChars / 2 >= 24);
    std::memcpy(out, digits_, kShortestNumberChars / 2);
    return out + length_;
  }

 private:
  char digits_[kShortestNumberChars];
  std::size_t length_ = 0;
  std::uint64_t bits_ = 0;
};

/// A RepeatedNumber's value, as a part of append_text.
struct RepeatedValue {
  RepeatedNumber& number;
  double value;
};

inline char* put_text_part(char* end, char c) {
  *end = c;
  return end + 1;
}
inline char* put_text_part(char* end, double v) { return write_shortest(end, v); }
inline char* put_text_part(char* end, const RepeatedValue& r) {
  return r.number.write(end, r.value);
}

/// The room a part takes: a character one, a number kShortestNumberChars (it writes at most half
/// of that and needs all of it).
template <class Part>
constexpr std::size_t text_part_room() {
  static_assert(std::is_same_v<Part, char> || std::is_same_v<Part, double> ||
                    std::is_same_v<Part, RepeatedValue>,
                "a part is a character, a double or a RepeatedValue");
  return std::is_same_v<Part, char> ? 1 : kShortestNumberChars;
}

/// Appends the parts, characters and numbers (written as append_number writes them), laid out
/// on the stack first and appended at once: a CLI point or hatch, a step of an SVG path. One
/// append rather than one a part, which was most of the cost of writing them but the numbers.
template <class... Parts>
void append_text(std::string& out, const Parts&... parts) {
  char text[(text_part_room<Parts>() + ...)];
  char* end = text;
  ((end = put_text_part(end, parts)), ...);
  out.append(text, end);
}

}  // namespace strata::io::detail
