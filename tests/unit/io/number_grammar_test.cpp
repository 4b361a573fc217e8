// The number grammar of the text formats (README "Numbers in text formats"): each token, written
// as a vertex coordinate in ASCII STL, OBJ, OFF and ASCII PLY (float and double properties), reads
// as the same value in every format, or is refused by every format with the same message naming
// the file, the line and the token.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "strata/io/read_mesh.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::TextMeshFormat;

constexpr const char* kNotANumber = "not a number";
constexpr const char* kNonFinite = "not a number (inf and nan are not accepted)";
constexpr const char* kHexadecimal = "not a number (hexadecimal is not accepted)";
constexpr const char* kTooLargeForDouble = "too large for a double (|x| <= 1.7976931348623157e308)";
constexpr const char* kTooLargeForFloat32 = "too large for a float32 (|x| <= 3.4028235e38)";
constexpr const char* kNotAnInteger =
    "not an integer (no decimal point or exponent where an integer is expected)";

/// One token: the value it reads as, or why it is refused. ASCII STL rounds to float32 (SPEC §2),
/// so a token can overflow there alone: `stl_reason` says so.
struct GrammarCase {
  const char* token;
  std::optional<double> value;
  const char* reason = nullptr;
  const char* stl_reason = nullptr;
};

GrammarCase accepted(const char* token, double value) { return {token, value}; }
GrammarCase refused(const char* token, const char* reason) { return {token, std::nullopt, reason}; }

const GrammarCase kCases[] = {
    accepted("10", 10.0),
    accepted("+10", 10.0),
    accepted("-10", -10.0),
    accepted("1E1", 10.0),
    accepted("1e+1", 10.0),
    accepted("2.5E-1", 0.25),
    accepted(".5e1", 5.0),
    accepted("5.", 5.0),
    accepted(".5", 0.5),
    accepted("-.5", -0.5),
    accepted("007", 7.0),
    accepted("-0", -0.0),
    accepted("+0", 0.0),
    accepted("-0.0e0", -0.0),
    accepted("0e999999", 0.0),
    accepted("1e-999", 0.0),    // underflow reads as zero...
    accepted("-1e-999", -0.0),  // ...of the token's sign
    refused("+-1", kNotANumber),
    refused("-+1", kNotANumber),
    refused("--1", kNotANumber),
    refused("++1", kNotANumber),
    refused("10abc", kNotANumber),
    refused("1..0", kNotANumber),
    refused("1.0.0", kNotANumber),
    refused("1,5", kNotANumber),
    refused(".", kNotANumber),
    refused("-", kNotANumber),
    refused("+", kNotANumber),
    refused("-.", kNotANumber),
    refused("1e", kNotANumber),
    refused("1e+", kNotANumber),
    refused("e5", kNotANumber),
    refused(".e1", kNotANumber),
    refused("1e5.0", kNotANumber),
    refused("0.5-1", kNotANumber),
    refused("nan", kNonFinite),
    refused("NaN", kNonFinite),
    refused("inf", kNonFinite),
    refused("-inf", kNonFinite),
    refused("+Infinity", kNonFinite),
    refused("0x1p3", kHexadecimal),
    refused("-0X10", kHexadecimal),
    {"1e999", std::nullopt, kTooLargeForDouble, kTooLargeForFloat32},
    {"-1e999", std::nullopt, kTooLargeForDouble, kTooLargeForFloat32},
    {"1.8e308", std::nullopt, kTooLargeForDouble, kTooLargeForFloat32},
    // A double, but beyond float32: only ASCII STL refuses it.
    {"1e39", 1e39, nullptr, kTooLargeForFloat32},
};

class NumberGrammar : public ::testing::TestWithParam<std::tuple<std::size_t, TextMeshFormat>> {};

TEST_P(NumberGrammar, SameValueOrSameRefusalInEveryFormat) {
  const GrammarCase& c = kCases[std::get<0>(GetParam())];
  const TextMeshFormat format = std::get<1>(GetParam());
  const bool stl = format == TextMeshFormat::StlAscii;
  const char* reason = stl && c.stl_reason != nullptr ? c.stl_reason : c.reason;

  test::TempDir dir("grammar");
  const test::TextMesh mesh = test::triangle_with_x(format, c.token);
  const auto path = test::write_text_file(dir / mesh.file_name, mesh.text);
  const auto soup = read_mesh(path);

  if (reason == nullptr) {
    ASSERT_TRUE(soup) << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), 1u);
    const double x = soup->triangles[0][1].x;
    EXPECT_EQ(x, *c.value);
    EXPECT_EQ(std::signbit(x), std::signbit(*c.value)) << x;
    return;
  }
  ASSERT_FALSE(soup) << "read as " << soup->triangles[0][1].x;
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().location, path.string() + ":" + std::to_string(mesh.token_line));
  EXPECT_EQ(soup.error().message, "bad number '" + std::string(c.token) + "': " + reason);
}

std::string grammar_case_name(const ::testing::TestParamInfo<NumberGrammar::ParamType>& info) {
  std::string token;
  for (const char ch : std::string(kCases[std::get<0>(info.param)].token)) {
    const bool alnum =
        (ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z');
    token += alnum       ? std::string(1, ch)
             : ch == '-' ? "minus"
             : ch == '+' ? "plus"
             : ch == '.' ? "dot"
                         : "_";
  }
  return std::string(test::format_name(std::get<1>(info.param))) + "_" +
         std::to_string(std::get<0>(info.param)) + "_" + token;
}

INSTANTIATE_TEST_SUITE_P(Tokens, NumberGrammar,
                         ::testing::Combine(::testing::Range<std::size_t>(0, std::size(kCases)),
                                            ::testing::ValuesIn(test::all_text_mesh_formats())),
                         grammar_case_name);

// ---------------------------------------------------------------------------------------------
// Integers: where a format declares one, a fraction or an exponent is refused, and so is a value
// outside the declared range.

struct IntegerCase {
  const char* name;
  const char* file_name;
  std::string text;
  std::size_t line;
  std::string message;
};

std::string ply_face(std::string_view count_type, std::string_view index_type,
                     std::string_view face) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list " +
         std::string(count_type) + " " + std::string(index_type) +
         " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" + std::string(face) + "\n";
}

const std::string kObjVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

class IntegerTokens : public ::testing::TestWithParam<IntegerCase> {};

TEST_P(IntegerTokens, AreRefusedNamingFileLineAndToken) {
  const IntegerCase& c = GetParam();
  test::TempDir dir("grammar");
  const auto path = test::write_text_file(dir / c.file_name, c.text);
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().location, path.string() + ":" + std::to_string(c.line));
  EXPECT_EQ(soup.error().message, c.message);
}

INSTANTIATE_TEST_SUITE_P(
    Files, IntegerTokens,
    ::testing::Values(
        IntegerCase{"obj_fraction", "t.obj", kObjVertices + "f 1 2 1.5\n", 4,
                    std::string("bad number '1.5': ") + kNotAnInteger},
        IntegerCase{"obj_exponent", "t.obj", kObjVertices + "f 1e2 2 3\n", 4,
                    std::string("bad number '1e2': ") + kNotAnInteger},
        IntegerCase{"obj_whole_with_point", "t.obj", kObjVertices + "f 1 2.0/2 3\n", 4,
                    std::string("bad number '2.0': ") + kNotAnInteger},
        IntegerCase{"obj_beyond_int64", "t.obj", kObjVertices + "f 1 2 99999999999999999999\n", 4,
                    "bad number '99999999999999999999': out of range for a 64-bit integer "
                    "(-9223372036854775808 to 9223372036854775807)"},
        IntegerCase{"obj_index_nan", "t.obj", kObjVertices + "f 1 2 nan\n", 4,
                    std::string("bad number 'nan': ") + kNonFinite},
        IntegerCase{"off_count_fraction", "t.off", "OFF\n3.0 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    2, std::string("bad number '3.0': ") + kNotAnInteger},
        IntegerCase{"off_negative_count", "t.off", "OFF\n3 -1 0\n0 0 0\n1 0 0\n0 1 0\n", 2,
                    "bad number '-1': out of range for an unsigned 64-bit integer (0 to "
                    "18446744073709551615)"},
        IntegerCase{"off_index_exponent", "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1e0 2\n",
                    6, std::string("bad number '1e0': ") + kNotAnInteger},
        IntegerCase{"off_index_sign_pair", "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 +-1 2\n",
                    6, "bad number '+-1': not a number"},
        IntegerCase{"ply_uchar_count_256", "t.ply", ply_face("uchar", "int", "256 0 1 2"), 13,
                    "bad number '256': out of range for an unsigned 8-bit integer (0 to 255)"},
        IntegerCase{"ply_uchar_count_minus_1", "t.ply", ply_face("uchar", "int", "-1 0 1 2"), 13,
                    "bad number '-1': out of range for an unsigned 8-bit integer (0 to 255)"},
        IntegerCase{"ply_int_index_fraction", "t.ply", ply_face("uchar", "int", "3 0 1 1.5"), 13,
                    std::string("bad number '1.5': ") + kNotAnInteger},
        IntegerCase{"ply_short_index_beyond", "t.ply", ply_face("uchar", "short", "3 0 1 32768"),
                    13, "bad number '32768': out of range for a 16-bit integer (-32768 to 32767)"},
        IntegerCase{"ply_element_count_fraction", "t.ply",
                    "ply\nformat ascii 1.0\nelement vertex 3.5\nproperty float x\nend_header\n", 3,
                    std::string("bad number '3.5': ") + kNotAnInteger}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(IntegerTokens, SignedAndZeroPaddedIndicesReadAsTheirValue) {
  test::TempDir dir("grammar");
  const std::array<Vec3, 3> expected{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  for (const auto& [name, text] : {
           std::pair<std::string, std::string>{"t.obj", kObjVertices + "f +1 002 -1\n"},
           {"t.off", "OFF\n+3 1 0\n0 0 0\n1 0 0\n0 1 0\n+3 -0 +1 002\n"},
           {"t.ply", ply_face("uchar", "int", "+3 -0 +1 002")},
       }) {
    const auto soup = read_mesh(test::write_text_file(dir / name, text));
    ASSERT_TRUE(soup) << name << ": " << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), 1u) << name;
    EXPECT_EQ(soup->triangles[0], expected) << name;
  }
}

}  // namespace
}  // namespace strata::io
