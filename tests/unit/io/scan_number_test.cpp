#include "strata/io/scan_number.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace strata::io {
namespace {

/// The value, or the fault, of a token scanned as a double.
void expect_real(const std::string& token, double value, NumberType type = NumberType::Float64) {
  const ScannedNumber<double> scanned = scan_real(token, type);
  ASSERT_TRUE(scanned.ok()) << token << ": " << bad_number_message(token, scanned.fault, type);
  EXPECT_EQ(scanned.value, value) << token;
  EXPECT_EQ(std::signbit(scanned.value), std::signbit(value)) << token;
}

void expect_real_fault(const std::string& token, NumberFault fault,
                       NumberType type = NumberType::Float64) {
  const ScannedNumber<double> scanned = scan_real(token, type);
  EXPECT_EQ(scanned.fault, fault) << token << " read as " << scanned.value;
  EXPECT_EQ(scanned.type, type) << token;
}

TEST(ScanReal, ReadsTheGrammarsNumbers) {
  expect_real("10", 10.0);
  expect_real("+10", 10.0);
  expect_real("-10", -10.0);
  expect_real("1E1", 10.0);
  expect_real("1e+1", 10.0);
  expect_real("1e-1", 0.1);
  expect_real(".5e1", 5.0);
  expect_real("5.", 5.0);
  expect_real(".5", 0.5);
  expect_real("-0", -0.0);
  expect_real("0.1", 0.1);
  expect_real("123456789012345678901234567890", 123456789012345678901234567890.0);
}

TEST(ScanReal, RefusesWhatIsNotInTheGrammar) {
  for (const char* token :
       {"",   "+-1", "-+1", "--1", "++1", "10abc", "1..0",   ".",  "-",  "+",   "-.",
        "1e", "1e+", "1e-", "e5",  ".e1", "1e5.0", "1.#INF", " 1", "1 ", "1_0", "\xd9\xa1"}) {
    expect_real_fault(token, NumberFault::NotANumber);
  }
  for (const char* token :
       {"nan", "NaN", "-nan", "nan(0x1)", "inf", "-inf", "+INF", "infinity", "-Infinity"}) {
    expect_real_fault(token, NumberFault::NonFiniteWord);
  }
  for (const char* token : {"0x1p3", "-0X10", "0x"}) {
    expect_real_fault(token, NumberFault::Hexadecimal);
  }
}

TEST(ScanReal, OverflowOfADoubleIsAnError) {
  expect_real("1.7976931348623157e308", DBL_MAX);
  expect_real("-1.7976931348623158e308", -DBL_MAX);  // rounds down to DBL_MAX
  for (const char* token : {"1e999", "-1e999", "1.8e308", "1000000e303", "0.00001e314",
                            "1e99999999999999999999999999"}) {
    expect_real_fault(token, NumberFault::TooLarge);
  }
}

TEST(ScanReal, UnderflowReadsAsZeroOfTheTokensSign) {
  expect_real("4.9406564584124654e-324", std::numeric_limits<double>::denorm_min());
  expect_real("1e-310", 1e-310);
  expect_real("2e-324", 0.0);
  expect_real("-2e-324", -0.0);
  expect_real("1e-999", 0.0);
  expect_real("-1e-999", -0.0);
  expect_real("100000e-330", 0.0);
  expect_real("-0.00000e-99999999999999999999999", -0.0);
  expect_real("0e999999", 0.0);
}

TEST(ScanReal, LongDigitStringsOverflowOrUnderflowByTheirMagnitude) {
  // Without a decimal point or an exponent, 400 digits are beyond any double; 400 zeros after
  // the point, and an explicit '+' exponent, decide the same way.
  expect_real_fault("1" + std::string(400, '0'), NumberFault::TooLarge);
  expect_real_fault("0001" + std::string(400, '0') + ".5", NumberFault::TooLarge);
  expect_real_fault("1E+400", NumberFault::TooLarge);
  expect_real("0." + std::string(400, '0') + "1", 0.0);
  expect_real("-0." + std::string(400, '0') + "1", -0.0);
}

TEST(ScanReal, Float32RoundsToNearestAndOverflowsBeyondItsRange) {
  expect_real("0.1", static_cast<double>(0.1f), NumberType::Float32);
  expect_real("4812345.3", 4812345.5, NumberType::Float32);
  expect_real("3.4028235e38", static_cast<double>(FLT_MAX), NumberType::Float32);
  expect_real("-3.40282356e38", -static_cast<double>(FLT_MAX), NumberType::Float32);
  expect_real("1e-50", 0.0, NumberType::Float32);
  expect_real("-1e-50", -0.0, NumberType::Float32);
  for (const char* token : {"3.40282357e38", "1e39", "-1e39", "1e999"}) {
    expect_real_fault(token, NumberFault::TooLarge, NumberType::Float32);
  }
  expect_real_fault("nan", NumberFault::NonFiniteWord, NumberType::Float32);
}

TEST(ScanInteger, ReadsWholeNumbersWithinTheTypesRange) {
  EXPECT_EQ(scan_signed("-128", NumberType::Int8).value, -128);
  EXPECT_EQ(scan_signed("+127", NumberType::Int8).value, 127);
  EXPECT_EQ(scan_unsigned("255", NumberType::UInt8).value, 255u);
  EXPECT_EQ(scan_unsigned("-0", NumberType::UInt8).value, 0u);
  EXPECT_TRUE(scan_unsigned("-0", NumberType::UInt8).ok());
  EXPECT_EQ(scan_signed("-32768", NumberType::Int16).value, -32768);
  EXPECT_EQ(scan_unsigned("65535", NumberType::UInt16).value, 65535u);
  EXPECT_EQ(scan_signed("-2147483648", NumberType::Int32).value, INT32_MIN);
  EXPECT_EQ(scan_unsigned("4294967295", NumberType::UInt32).value, UINT32_MAX);
  EXPECT_EQ(scan_signed("-9223372036854775808", NumberType::Int64).value, INT64_MIN);
  EXPECT_EQ(scan_signed("9223372036854775807", NumberType::Int64).value, INT64_MAX);
  EXPECT_EQ(scan_unsigned("18446744073709551615", NumberType::UInt64).value, UINT64_MAX);
  EXPECT_EQ(scan_unsigned("000000000000000000000000042", NumberType::UInt8).value, 42u);
}

TEST(ScanInteger, RefusesValuesOutsideTheTypesRange) {
  const struct {
    const char* token;
    NumberType type;
  } cases[] = {{"-129", NumberType::Int8},
               {"128", NumberType::Int8},
               {"256", NumberType::UInt8},
               {"-1", NumberType::UInt8},
               {"32768", NumberType::Int16},
               {"65536", NumberType::UInt16},
               {"2147483648", NumberType::Int32},
               {"-2147483649", NumberType::Int32},
               {"4294967296", NumberType::UInt32},
               {"9223372036854775808", NumberType::Int64},
               {"-9223372036854775809", NumberType::Int64},
               {"18446744073709551616", NumberType::UInt64},
               {"-1", NumberType::UInt64},
               {"99999999999999999999999999999", NumberType::Int64}};
  for (const auto& c : cases) {
    const bool is_signed = c.type == NumberType::Int8 || c.type == NumberType::Int16 ||
                           c.type == NumberType::Int32 || c.type == NumberType::Int64;
    const NumberFault fault =
        is_signed ? scan_signed(c.token, c.type).fault : scan_unsigned(c.token, c.type).fault;
    EXPECT_EQ(fault, NumberFault::OutOfRange) << c.token;
  }
}

TEST(ScanInteger, RefusesFractionsAndExponentsAndWhatIsNotANumber) {
  for (const char* token : {"1.5", "1.0", "1.", ".5", "1e2", "1E0", "-2e-1"}) {
    EXPECT_EQ(scan_signed(token, NumberType::Int64).fault, NumberFault::NotAnInteger) << token;
    EXPECT_EQ(scan_unsigned(token, NumberType::UInt8).fault, NumberFault::NotAnInteger) << token;
  }
  for (const char* token : {"", "+-1", "--1", "1a", "-", "1e", "."}) {
    EXPECT_EQ(scan_signed(token, NumberType::Int32).fault, NumberFault::NotANumber) << token;
  }
  EXPECT_EQ(scan_unsigned("nan", NumberType::UInt32).fault, NumberFault::NonFiniteWord);
  EXPECT_EQ(scan_unsigned("0x10", NumberType::UInt32).fault, NumberFault::Hexadecimal);
}

TEST(BadNumberMessage, QuotesTheTokenAndSaysWhy) {
  EXPECT_EQ(bad_number_message("1e999", NumberFault::TooLarge, NumberType::Float64),
            "bad number '1e999': too large for a double (|x| <= 1.7976931348623157e308)");
  EXPECT_EQ(bad_number_message("1e39", NumberFault::TooLarge, NumberType::Float32),
            "bad number '1e39': too large for a float32 (|x| <= 3.4028235e38)");
  EXPECT_EQ(bad_number_message("+-1", NumberFault::NotANumber, NumberType::Float64),
            "bad number '+-1': not a number");
  EXPECT_EQ(bad_number_message("nan", NumberFault::NonFiniteWord, NumberType::Float64),
            "bad number 'nan': not a number (inf and nan are not accepted)");
  EXPECT_EQ(bad_number_message("0x1p3", NumberFault::Hexadecimal, NumberType::Float64),
            "bad number '0x1p3': not a number (hexadecimal is not accepted)");
  EXPECT_EQ(bad_number_message("1.5", NumberFault::NotAnInteger, NumberType::Int64),
            "bad number '1.5': not an integer (no decimal point or exponent where an integer is "
            "expected)");
  EXPECT_EQ(bad_number_message("256", NumberFault::OutOfRange, NumberType::UInt8),
            "bad number '256': out of range for an unsigned 8-bit integer (0 to 255)");
}

TEST(BadNumberMessage, ShowsControlBytesAndCutsLongTokens) {
  EXPECT_EQ(bad_number_message("1\x10", NumberFault::NotANumber, NumberType::Float64),
            "bad number '1\\x10': not a number");
  EXPECT_EQ(
      bad_number_message(std::string(50, '7') + "x", NumberFault::NotANumber, NumberType::Float64),
      "bad number '" + std::string(40, '7') + "...': not a number");
}

TEST(BadNumberMessage, ShowsBytesBeyondAsciiAsHex) {
  EXPECT_EQ(bad_number_message("1\xc3\xa9", NumberFault::NotANumber, NumberType::Float64),
            "bad number '1\\xc3\\xa9': not a number");
  EXPECT_EQ(bad_number_message("\x7f", NumberFault::NotANumber, NumberType::Float64),
            "bad number '\\x7f': not a number");
}

TEST(BadNumber, IsABadInputErrorAtTheGivenLocation) {
  const Error error = bad_number("t.ply:11", "1e999", scan_real("1e999", NumberType::Float64));
  EXPECT_EQ(error.code, ErrorCode::BadInput);
  EXPECT_EQ(error.to_string(),
            "t.ply:11: bad number '1e999': too large for a double (|x| <= 1.7976931348623157e308)");
}

}  // namespace
}  // namespace strata::io
