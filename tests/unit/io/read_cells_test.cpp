#include "strata/io/read_cells.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "strata/export/cells_writer.hpp"
#include "support/mesh_reading.hpp"
#include "support/result_checks.hpp"
#include "support/sink_runs.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::contains;
using test::read_file;
using testing::run_sink;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

using Counts = std::array<std::uint64_t, 3>;

std::filesystem::path write_small(const ScratchDir& dir, CellsEncoding encoding) {
  const auto path = dir / (encoding == CellsEncoding::Binary ? "part.cells" : "part.cells.txt");
  auto sink = make_cells_writer(path, encoding);
  testing::expect_run(*sink, small_run(), small_layers());
  return path;
}

std::vector<CellClass> all_small_cells() {
  std::vector<CellClass> cells;
  for (const auto& layer : small_layers()) {
    cells.insert(cells.end(), layer.cells.begin(), layer.cells.end());
  }
  return cells;
}

void expect_small_header(const CellsHeader& h) {
  const GridSpec expected = small_run().grid;
  EXPECT_EQ(h.grid.nx, expected.nx);
  EXPECT_EQ(h.grid.ny, expected.ny);
  EXPECT_EQ(h.grid.nz, expected.nz);
  EXPECT_EQ(h.grid.x0, expected.x0);
  EXPECT_EQ(h.grid.y0, expected.y0);
  EXPECT_EQ(h.grid.z0, expected.z0);
  EXPECT_EQ(h.grid.dx, expected.dx);
  EXPECT_EQ(h.grid.dy, expected.dy);
  EXPECT_EQ(h.grid.dz, expected.dz);
  EXPECT_EQ(h.shell_mm, 0.75);
}

/// Reads `path`, expecting a BadInput error; returns it.
Error read_cells_error(const std::filesystem::path& path) {
  const Error error = test::error_of(read_cells(path), path.string());
  EXPECT_EQ(error.code, ErrorCode::BadInput);
  return error;
}

TEST(CellsReader, BinaryRoundTripGivesTheWrittenClasses) {
  ScratchDir dir;
  auto read = read_cells(write_small(dir, CellsEncoding::Binary));
  ASSERT_TRUE(read) << read.error().to_string();
  EXPECT_EQ(read->header.encoding, CellsEncoding::Binary);
  expect_small_header(read->header);
  EXPECT_EQ(read->cells, all_small_cells());
  EXPECT_EQ(read->at(3, 2, 0), CellClass::Boundary);
  EXPECT_EQ(read->at(1, 1, 1), CellClass::Interior);
}

TEST(CellsReader, AsciiRoundTripGivesTheWrittenClasses) {
  ScratchDir dir;
  auto read = read_cells(write_small(dir, CellsEncoding::Ascii));
  ASSERT_TRUE(read) << read.error().to_string();
  EXPECT_EQ(read->header.encoding, CellsEncoding::Ascii);
  expect_small_header(read->header);
  EXPECT_EQ(read->cells, all_small_cells());
}

TEST(CellsReader, AsciiRoundTripKeepsAwkwardDoublesBitForBit) {
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.grid.x0 = 0.1 + 0.2;
  run.grid.y0 = -1.0 / 3.0;
  run.grid.z0 = 1e-300;
  run.grid.dx = 0.1;
  run.options.shell_mm = 2.0 / 3.0;
  auto sink = make_cells_writer(dir / "a.cells.txt", CellsEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, run, small_layers()));
  auto read = read_cells(dir / "a.cells.txt");
  ASSERT_TRUE(read) << read.error().to_string();
  EXPECT_EQ(read->header.grid.x0, run.grid.x0);
  EXPECT_EQ(read->header.grid.y0, run.grid.y0);
  EXPECT_EQ(read->header.grid.z0, run.grid.z0);
  EXPECT_EQ(read->header.grid.dx, run.grid.dx);
  EXPECT_EQ(read->header.shell_mm, run.options.shell_mm);
}

TEST(CellsReader, SummaryCountsClassesInTotalAndPerLayer) {
  ScratchDir dir;
  auto summary = summarize_cells(write_small(dir, CellsEncoding::Binary));
  ASSERT_TRUE(summary) << summary.error().to_string();
  expect_small_header(summary->header);
  EXPECT_EQ(summary->class_counts, (Counts{5, 9, 16}));
  ASSERT_EQ(summary->layer_counts.size(), 2u);
  EXPECT_EQ(summary->layer_counts[0], (Counts{5, 6, 4}));
  EXPECT_EQ(summary->layer_counts[1], (Counts{0, 3, 12}));
}

TEST(CellsReader, SummaryGivesTheBoundsOfTheSolidCells) {
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.grid.nz = 3;
  auto layers = small_layers();
  layers.push_back(layers[0]);
  layers[2].layer = 2;
  layers[2].cells.assign(15, CellClass::Empty);
  layers[0].cells.assign(15, CellClass::Empty);
  layers[0].cells[1 * 5 + 3] = CellClass::Interior;  // (3, 1, 0)
  auto sink = make_cells_writer(dir / "b.cells");
  ASSERT_TRUE(run_sink(*sink, run, layers));
  auto summary = summarize_cells(dir / "b.cells");
  ASSERT_TRUE(summary) << summary.error().to_string();
  ASSERT_TRUE(summary->solid_bounds.has_value());
  const CellIndexBox& b = *summary->solid_bounds;
  EXPECT_EQ(b.i_min, 0u);
  EXPECT_EQ(b.i_max, 4u);
  EXPECT_EQ(b.j_min, 0u);
  EXPECT_EQ(b.j_max, 2u);
  EXPECT_EQ(b.k_min, 0u);
  EXPECT_EQ(b.k_max, 1u);
}

TEST(CellsReader, SummaryOfAnAllEmptyFileHasNoBounds) {
  ScratchDir dir;
  auto layers = small_layers();
  for (auto& layer : layers) layer.cells.assign(15, CellClass::Empty);
  auto sink = make_cells_writer(dir / "e.cells");
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  auto summary = summarize_cells(dir / "e.cells");
  ASSERT_TRUE(summary);
  EXPECT_FALSE(summary->solid_bounds.has_value());
  EXPECT_EQ(summary->class_counts, (Counts{30, 0, 0}));
}

TEST(CellsReader, BothEncodingsSummarizeAlike) {
  ScratchDir dir;
  auto binary = summarize_cells(write_small(dir, CellsEncoding::Binary));
  auto ascii = summarize_cells(write_small(dir, CellsEncoding::Ascii));
  ASSERT_TRUE(binary);
  ASSERT_TRUE(ascii);
  EXPECT_EQ(binary->class_counts, ascii->class_counts);
  EXPECT_EQ(binary->layer_counts, ascii->layer_counts);
}

TEST(CellsReader, LayerVisitorSeesLayersInOrderAndCanStop) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  std::vector<std::uint32_t> seen;
  auto read = read_cells_layers(
      path,
      [&](const CellsHeader&, std::uint32_t k, std::span<const CellClass> cells) -> Result<void> {
        seen.push_back(k);
        EXPECT_EQ(cells.size(), 15u);
        return Error{ErrorCode::Usage, "stop", "visitor"};
      });
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error().message, "stop");
  EXPECT_EQ(seen, std::vector<std::uint32_t>{0});
}

// ---------------------------------------------------------------------------- binary errors

TEST(CellsReader, MissingFileIsBadInput) {
  ScratchDir dir;
  const Error e = read_cells_error(dir / "nope.cells");
  EXPECT_EQ(e.location, (dir / "nope.cells").string());
}

/// The binary file of small_run() edited, and how the reader must refuse it: a message containing
/// `part` and, unless `place` is null, the location `path + place`.
struct BinaryEditCase {
  const char* name;
  std::string (*edit)(std::string file);
  const char* place;
  const char* part;
};

void PrintTo(const BinaryEditCase& c, std::ostream* os) { *os << c.name; }

class CellsReaderBinaryEdit : public ::testing::TestWithParam<BinaryEditCase> {};

TEST_P(CellsReaderBinaryEdit, IsRejected) {
  const BinaryEditCase& c = GetParam();
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  test::write_text_file(path, c.edit(read_file(path)));
  const Error e = read_cells_error(path);
  if (c.place != nullptr) {
    EXPECT_EQ(e.location, path.string() + c.place);
  }
  EXPECT_TRUE(contains(e.message, c.part)) << e.message;
}

INSTANTIATE_TEST_SUITE_P(
    CellsReader, CellsReaderBinaryEdit,
    ::testing::Values(BinaryEditCase{"BadMagic",
                                     +[](std::string file) {
                                       file[7] = '2';  // STRCELL2
                                       return file;
                                     },
                                     "", "STRCELL1"},
                      BinaryEditCase{"TruncatedHeader",
                                     +[](std::string file) { return file.substr(0, 40); }, nullptr,
                                     "ends after 40 bytes"},
                      BinaryEditCase{"WrongHeaderSizeField",
                                     +[](std::string file) {
                                       file[8] = 96;
                                       return file;
                                     },
                                     nullptr, "header size field is 96"},
                      BinaryEditCase{"TruncatedLayersWithTheExpectedLength",
                                     +[](std::string file) { return file.substr(0, 86); }, nullptr,
                                     "86 bytes, shorter than the 88 bytes"},
                      BinaryEditCase{"TrailingBytes",
                                     +[](std::string file) { return file + std::string(1, '\0'); },
                                     nullptr, "89 bytes, longer than the 88 bytes"},
                      BinaryEditCase{"ZeroSizedGrid",
                                     +[](std::string file) {
                                       file[12] = 0;  // nx = 0
                                       return file.substr(0, 80);
                                     },
                                     nullptr, "0 x 3 x 2"},
                      BinaryEditCase{"NonZeroPaddingBits",
                                     +[](std::string file) {
                                       // layer 0's last byte 0x70 with a padding bit set
                                       file[83] = static_cast<char>(0x71);
                                       return file;
                                     },
                                     ": layer 0", "padding"}),
    [](const ::testing::TestParamInfo<BinaryEditCase>& info) { return info.param.name; });

TEST(CellsReader, ReservedCodeNamesLayerRowAndCell) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  std::string file = read_file(path);
  // Layer 1, cell index 6 = row 1, cell 1: byte 80 + 4 + 1, bits 3..2 (0xF5 -> 0xF9: 01 -> 10).
  ASSERT_EQ(static_cast<unsigned char>(file[85]), 0xF5);
  file[85] = static_cast<char>(0xF9);
  test::write_text_file(path, file);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ": layer 1, row 1, cell 1");
  EXPECT_TRUE(contains(e.message, "reserved cell code 10")) << e.message;
}

TEST(CellsReader, SummaryStopsAtTheSameErrors) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  test::write_text_file(path, read_file(path).substr(0, 84));
  auto summary = summarize_cells(path);
  ASSERT_FALSE(summary);
  EXPECT_EQ(summary.error().code, ErrorCode::BadInput);
}

TEST(CellsReader, UnknownContentIsNotACellsFile) {
  ScratchDir dir;
  test::write_text_file(dir / "x.cells", "solid cube\nfacet normal 0 0 1\n");
  const Error e = read_cells_error(dir / "x.cells");
  EXPECT_TRUE(contains(e.message, "not a cells file")) << e.message;
}

// ----------------------------------------------------------------------------- ascii errors

/// The ASCII file of small_run() with line `number` (1-based) replaced.
std::filesystem::path ascii_with_line(const ScratchDir& dir, std::size_t number,
                                      const std::string& replacement) {
  const auto path = write_small(dir, CellsEncoding::Ascii);
  auto lines = testing::lines_of(read_file(path));
  lines.at(number - 1) = replacement;
  std::string text;
  for (const auto& line : lines) text += line + "\n";
  test::write_text_file(path, text);
  return path;
}

/// One line of the ASCII file of small_run() replaced, and how the reader must refuse it: at
/// `error_line`, with the whole `message`, or a message containing `part`, or (both null) with
/// only the place checked.
struct AsciiLineCase {
  const char* name;
  std::size_t line;
  const char* replacement;
  std::size_t error_line;
  const char* message = nullptr;
  const char* part = nullptr;
};

void PrintTo(const AsciiLineCase& c, std::ostream* os) { *os << c.name; }

class CellsReaderAsciiLine : public ::testing::TestWithParam<AsciiLineCase> {};

TEST_P(CellsReaderAsciiLine, IsRefusedNamingTheLine) {
  const AsciiLineCase& c = GetParam();
  ScratchDir dir;
  const auto path = ascii_with_line(dir, c.line, c.replacement);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":" + std::to_string(c.error_line));
  if (c.message != nullptr) {
    EXPECT_EQ(e.message, c.message);
  }
  if (c.part != nullptr) {
    EXPECT_TRUE(contains(e.message, c.part)) << e.message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    CellsReader, CellsReaderAsciiLine,
    ::testing::Values(
        AsciiLineCase{"ShortRow", 8, "11000100", 8, nullptr,
                      "row 1 of layer 0 has 8 characters; expected 10"},
        AsciiLineCase{"ReservedCodeNamesTheCell", 12, "1101100111", 12, nullptr,
                      "reserved cell code 10 at layer 1, row 1, cell 2"},
        AsciiLineCase{"ForeignCharacter", 7, "00011x1101", 7, nullptr, "cell 2"},
        AsciiLineCase{"WrongLayerIndex", 10, "layer 2 z=1.625", 10, nullptr,
                      "layer 2 found where layer 1 was expected"},
        AsciiLineCase{"MalformedLayerLine", 10, "layer 1 at 1.625", 10},
        AsciiLineCase{"BadHeaderValue", 3, "origin -1.5 abc 0.125", 3},
        // The numbers of an ASCII cells file follow the grammar of every text format (README
        // "Numbers in text formats") and are refused with the same message.
        AsciiLineCase{"HeaderNumberTooLarge", 3, "origin -1.5 1e999 0.125", 3,
                      "bad number '1e999': too large for a double (|x| <= 1.7976931348623157e308)"},
        AsciiLineCase{"GridSizeWithAFraction", 2, "grid 5 3.0 2", 2,
                      "bad number '3.0': not an integer (no decimal point or exponent where an "
                      "integer is expected)"},
        AsciiLineCase{"LayerHeightNan", 10, "layer 1 z=nan", 10,
                      "bad number 'nan': not a number (inf and nan are not accepted)"},
        AsciiLineCase{"UnknownHeaderKey", 5, "thickness 0.75", 5, nullptr,
                      "unknown header key 'thickness'"},
        AsciiLineCase{"UnsupportedVersionNamesBothVersionLines", 1, "strata-cells 2", 1,
                      "unsupported version line 'strata-cells 2'; expected 'strata-cells 1'"},
        // It starts like an ASCII cells file, so the ASCII reader says what the first line
        // must be.
        AsciiLineCase{"AnotherFirstLine", 1, "strata-cells-1", 1,
                      "expected the first line 'strata-cells 1'"},
        AsciiLineCase{"HeaderKeyGivenTwice", 5, "grid 5 3 2", 5,
                      "'grid' appears twice in the header"},
        AsciiLineCase{"HeaderLineWithTooFewValuesShowsItsShape", 4, "spacing 0.5 0.25", 4,
                      "expected 'spacing dx dy dz'"},
        AsciiLineCase{"MissingHeaderKeyNamedAtTheFirstLayer", 5, "", 6,
                      "the header has no 'shell' line before the first layer"}),
    [](const ::testing::TestParamInfo<AsciiLineCase>& info) { return info.param.name; });

TEST(CellsReader, AsciiSignedNumbersAreRead) {
  ScratchDir dir;
  const auto path = ascii_with_line(dir, 10, "layer +1 z=+1.625e0");
  auto read = read_cells(path);
  ASSERT_TRUE(read) << read.error().to_string();
  EXPECT_EQ(read->cells, all_small_cells());
}

TEST(CellsReader, AsciiTruncatedFileSaysWhatIsMissing) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Ascii);
  auto lines = testing::lines_of(read_file(path));
  std::string text;
  for (std::size_t n = 0; n < 11; ++n) text += lines[n] + "\n";  // stops inside layer 1
  test::write_text_file(path, text);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":12");
  EXPECT_TRUE(contains(e.message, "file ends inside layer 1: 1 of 3 rows")) << e.message;
}

TEST(CellsReader, AsciiExtraContentAfterTheLastLayerIsRejected) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Ascii);
  test::write_text_file(path, read_file(path) + "\n0000000000\n");
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":15");
}

/// The first `count` lines of the ASCII file of small_run().
std::filesystem::path ascii_first_lines(const ScratchDir& dir, std::size_t count) {
  const auto path = write_small(dir, CellsEncoding::Ascii);
  const auto lines = testing::lines_of(read_file(path));
  std::string text;
  for (std::size_t n = 0; n < count; ++n) text += lines.at(n) + "\n";
  test::write_text_file(path, text);
  return path;
}

TEST(CellsReader, AsciiHeaderWithoutLayersSaysHowManyWereExpected) {
  ScratchDir dir;
  const auto path = ascii_first_lines(dir, 5);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":6");
  EXPECT_EQ(e.message, "file ends after the header; expected 2 layers");
}

TEST(CellsReader, AsciiFileEndingBetweenLayersSaysHowManyWereRead) {
  ScratchDir dir;
  const auto path = ascii_first_lines(dir, 9);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":10");
  EXPECT_EQ(e.message, "file ends after 1 of 2 layers");
}

TEST(CellsReader, AsciiHeaderValuesAreCheckedAsInBinaryFiles) {
  struct Case {
    std::size_t line;
    const char* replacement;
    const char* message;
  };
  const Case cases[] = {
      {2, "grid 5 0 2", "grid 5 x 0 x 2 has no cells; every size must be at least 1"},
      {4, "spacing 0.5 -0.25 1", "spacing 0.5 -0.25 1 must be positive and finite"},
      {4, "spacing 0.5 0.25 0", "spacing 0.5 0.25 0 must be positive and finite"},
      {5, "shell -0.75", "shell thickness -0.75 must be finite and not negative"},
  };
  for (const Case& c : cases) {
    ScratchDir dir;
    const auto path = ascii_with_line(dir, c.line, c.replacement);
    const Error e = read_cells_error(path);
    EXPECT_EQ(e.location, path.string() + ": header") << c.replacement;
    EXPECT_EQ(e.message, c.message);
  }
}

TEST(CellsReader, BinaryNonFiniteOriginIsRejected) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  std::string file = read_file(path);
  const unsigned char inf_le[8] = {0, 0, 0, 0, 0, 0, 0xF0, 0x7F};
  for (int b = 0; b < 8; ++b) file[32 + b] = static_cast<char>(inf_le[b]);  // y0 = +inf
  test::write_text_file(path, file);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string());
  EXPECT_EQ(e.message, "origin -1.5 inf 0.125 is not finite");
}

TEST(CellsReader, BinaryGridTooLargeToAddressIsRejectedBeforeItsLength) {
  // 4294967295 x 4294967295 cells a layer take 2^62 bytes: five layers overflow a 64-bit size.
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Binary);
  std::string file = read_file(path).substr(0, 80);
  for (int b = 12; b < 20; ++b) file[b] = static_cast<char>(0xFF);  // nx, ny = 2^32 - 1
  file[20] = 5;                                                     // nz = 5
  test::write_text_file(path, file);
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string());
  EXPECT_EQ(e.message, "grid 4294967295 x 4294967295 x 5 is too large to address");
}

TEST(CellsReader, FolderIsNotACellsFile) {
  ScratchDir dir;
  const Error e = read_cells_error(dir.path());
  EXPECT_EQ(e.location, dir.path().string());
  EXPECT_EQ(e.message, "is a folder, not a cells file");
}

TEST(CellsReader, FileShorterThanAnyCellsFileIsRejected) {
  ScratchDir dir;
  for (const std::string& bytes : {std::string(), std::string("ST")}) {
    test::write_text_file(dir / "tiny.cells", bytes);
    const Error e = read_cells_error(dir / "tiny.cells");
    EXPECT_EQ(e.location, (dir / "tiny.cells").string());
    EXPECT_EQ(e.message,
              "file of " + std::to_string(bytes.size()) + " bytes is too short to be a cells file");
  }
}

TEST(CellsReader, AsciiAcceptsCrLfLineEnds) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Ascii);
  std::string crlf;
  for (const auto& line : testing::lines_of(read_file(path))) crlf += line + "\r\n";
  test::write_text_file(path, crlf);
  auto read = read_cells(path);
  ASSERT_TRUE(read) << read.error().to_string();
  EXPECT_EQ(read->cells, all_small_cells());
}

// ------------------------------------------------------------------ conformance vectors

/// Reads a file of ../shared/vectors and checks its grid, spacing, shell and class counts against
/// the table of vectors/README.md.
void expect_vector(const std::string& name, std::array<std::uint32_t, 3> n, double cell,
                   double layer, double shell, Counts counts) {
  const std::filesystem::path path = std::filesystem::path(STRATA_SHARED_DIR) / "vectors" / name;
  auto file = read_cells(path);
  ASSERT_TRUE(file) << file.error().to_string();
  const GridSpec& g = file->header.grid;
  EXPECT_EQ(g.nx, n[0]);
  EXPECT_EQ(g.ny, n[1]);
  EXPECT_EQ(g.nz, n[2]);
  EXPECT_EQ(g.dx, cell);
  EXPECT_EQ(g.dy, cell);
  EXPECT_EQ(g.dz, layer);
  EXPECT_EQ(file->header.shell_mm, shell);
  Counts seen{};
  for (CellClass c : file->cells) {
    ++seen[c == CellClass::Empty ? 0 : c == CellClass::Interior ? 1 : 2];
  }
  EXPECT_EQ(seen, counts);
  auto summary = summarize_cells(path);
  ASSERT_TRUE(summary) << summary.error().to_string();
  EXPECT_EQ(summary->class_counts, counts);
}

TEST(CellsReaderVectors, TetrahedronCell1Distance) {
  expect_vector("tetrahedron__cell1_layer1_shell1.5_distance_nonzero.cells", {10, 10, 10}, 1, 1,
                1.5, {835, 10, 155});
}

TEST(CellsReaderVectors, TetrahedronCellHalfLayers) {
  expect_vector("tetrahedron__cell0.5_layer0.25_shell1_layers_nonzero.cells", {20, 20, 40}, 0.5,
                0.25, 1, {13340, 70, 2590});
}

TEST(CellsReaderVectors, StackedBoxesLayers) {
  expect_vector("stacked_boxes__cell1_layer1_shell1_layers_nonzero.cells", {6, 6, 4}, 1, 1, 1,
                {40, 20, 84});
}

TEST(CellsReaderVectors, StackedBoxesDistanceEvenOdd) {
  expect_vector("stacked_boxes__cell0.5_layer0.5_shell0.6_distance_evenodd.cells", {12, 12, 7}, 0.5,
                0.5, 0.6, {320, 172, 516});
}

TEST(CellsReaderVectors, WallsThroughCentres) {
  expect_vector("walls_through_centres__cell1_layer1_shell1_layers_nonzero.cells", {4, 4, 3}, 1, 1,
                1, {15, 2, 31});
}

TEST(CellsReaderVectors, OverlappingBoxesNonZero) {
  expect_vector("overlapping_boxes__cell1_layer1_shell1_layers_nonzero.cells", {6, 4, 4}, 1, 1, 1,
                {24, 12, 60});
}

TEST(CellsReaderVectors, OverlappingBoxesEvenOdd) {
  expect_vector("overlapping_boxes__cell1_layer1_shell1_layers_evenodd.cells", {6, 4, 4}, 1, 1, 1,
                {32, 0, 64});
}

TEST(CellsReader, AsciiBadNumbersOfEveryHeaderKeyAndTheLayerIndexNameTheirLine) {
  struct Case {
    std::size_t line;
    const char* replacement;
    const char* token;
  };
  const Case cases[] = {{2, "grid 5 x 2", "x"},
                        {4, "spacing 0.5 x 1", "x"},
                        {5, "shell t", "t"},
                        {10, "layer one z=1.625", "one"}};
  for (const Case& c : cases) {
    ScratchDir dir;
    const auto path = ascii_with_line(dir, c.line, c.replacement);
    const Error e = read_cells_error(path);
    EXPECT_EQ(e.location, path.string() + ":" + std::to_string(c.line)) << c.replacement;
    EXPECT_EQ(e.message.rfind(std::string("bad number '") + c.token + "'", 0), 0u) << e.message;
  }
}

TEST(CellsReader, AsciiHeaderEndingWithoutAKeyIsNamedAfterTheLastLine) {
  ScratchDir dir;
  const auto path = write_small(dir, CellsEncoding::Ascii);
  const auto lines = testing::lines_of(read_file(path));
  test::write_text_file(path,
                        lines[0] + "\n" + lines[1] + "\n" + lines[2] + "\n" + lines[3] + "\n");
  const Error e = read_cells_error(path);
  EXPECT_EQ(e.location, path.string() + ":5");
  EXPECT_EQ(e.message, "the header has no 'shell' line before the first layer");
}

TEST(CellsReader, AsciiLineErrorsNameTheirLineAndSayWhatWasExpected) {
  struct Case {
    std::size_t line;
    const char* replacement;
    const char* message;
  };
  const Case cases[] = {
      {3, "grid 5 3 2", "'grid' appears twice in the header"},
      {4, "origin 0 0 0", "'origin' appears twice in the header"},
      {6, "shell 1", "'shell' appears twice in the header"},
      {10, "layers 1 z=1.625", "expected 'layer 1 z=<number>'"},
      {10, "layer 1 q=1.625", "expected 'layer 1 z=<number>'"},
      {7, "0001111x01",
       "'1x' at layer 0, row 0, cell 3 (column 7) is not a cell code; expected 00, 01 or 11"},
      {7, "000111110x",
       "'0x' at layer 0, row 0, cell 4 (column 9) is not a cell code; expected 00, 01 or 11"},
      {7, "x001111101",
       "'x0' at layer 0, row 0, cell 0 (column 1) is not a cell code; expected 00, 01 or 11"},
  };
  for (const Case& c : cases) {
    ScratchDir dir;
    const auto path = ascii_with_line(dir, c.line, c.replacement);
    const Error e = read_cells_error(path);
    EXPECT_EQ(e.location, path.string() + ":" + std::to_string(c.line)) << c.replacement;
    EXPECT_EQ(e.message, c.message);
  }
}

TEST(CellsReader, AsciiMissingHeaderKeysAreNamedInOrder) {
  struct Case {
    std::size_t line;
    const char* key;
  };
  for (const Case& c : {Case{2, "grid"}, Case{3, "origin"}, Case{4, "spacing"}}) {
    ScratchDir dir;
    const auto path = ascii_with_line(dir, c.line, "");
    const Error e = read_cells_error(path);
    EXPECT_EQ(e.location, path.string() + ":6");
    EXPECT_EQ(e.message,
              std::string("the header has no '") + c.key + "' line before the first layer");
  }
}

TEST(CellsReader, AsciiTabsTrailingBlanksAndBlankLinesBetweenLayersAreAccepted) {
  ScratchDir dir;
  const auto path = ascii_with_line(dir, 10, " \t\n\nlayer\t1  z=1.625 \t");
  auto read = read_cells(path);
  ASSERT_TRUE(read) << read.error().to_string();
  expect_small_header(read->header);
  EXPECT_EQ(read->cells, all_small_cells());
}

TEST(CellsReader, BinaryNonFiniteHeaderValuesAreRejected) {
  // Values no ASCII file can hold (the number scanner refuses inf and nan), each at its offset.
  struct Case {
    int offset;
    double value;
    const char* message;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Case cases[] = {
      {24, -inf, "origin -inf 2.25 0.125 is not finite"},
      {40, nan, "origin -1.5 2.25 nan is not finite"},
      {48, inf, "spacing inf 0.25 1 must be positive and finite"},
      {56, nan, "spacing 0.5 nan 1 must be positive and finite"},
      {64, inf, "spacing 0.5 0.25 inf must be positive and finite"},
      {72, nan, "shell thickness nan must be finite and not negative"},
  };
  for (const Case& c : cases) {
    ScratchDir dir;
    const auto path = write_small(dir, CellsEncoding::Binary);
    std::string file = read_file(path);
    std::uint64_t bits = 0;
    std::memcpy(&bits, &c.value, sizeof bits);
    for (int b = 0; b < 8; ++b) file[c.offset + b] = static_cast<char>((bits >> (8 * b)) & 0xFF);
    test::write_text_file(path, file);
    const Error e = read_cells_error(path);
    EXPECT_EQ(e.location, path.string());
    EXPECT_EQ(e.message, c.message);
  }
}

}  // namespace
}  // namespace strata::io
