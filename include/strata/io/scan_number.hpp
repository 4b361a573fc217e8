#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "strata/core/error.hpp"

namespace strata::io {

/// The type a text token is read as. Real numbers are read as double (OBJ, OFF, PLY, cells
/// files) or rounded to the nearest float32 (ASCII STL, SPEC §2); integers have a width and a
/// signedness (PLY's declared types, OBJ indices, OFF and PLY counts, cells grid sizes).
enum class NumberType {
  Float64,
  Float32,
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Int64,
  UInt64
};

/// Why a token was refused.
enum class NumberFault {
  None,           ///< the token is a number of the wanted type
  NotANumber,     ///< does not follow the grammar (empty, `+-1`, `10abc`, `1..0`, `.`, `1e`)
  NonFiniteWord,  ///< `inf`, `infinity` or `nan` (any case, optionally signed)
  Hexadecimal,    ///< `0x...`
  NotAnInteger,   ///< a real number (fraction or exponent) where an integer is declared
  TooLarge,       ///< a real number whose magnitude overflows the type (1e999 as a double)
  OutOfRange,     ///< an integer outside the type's range (256 as UInt8, -1 as UInt64)
};

/// A scanned token: the value (rounded to the type), or why there is none.
template <class T>
struct ScannedNumber {
  T value{};
  NumberFault fault = NumberFault::None;
  NumberType type = NumberType::Float64;

  /// True when the token was a number of the type (no fault).
  bool ok() const { return fault == NumberFault::None; }
};

/// Reads one whole blank-free token as a real number. The grammar, the same for every text
/// format: at most one sign (`+` or `-`); digits with an optional decimal point (`5.` and `.5`
/// are numbers, a lone `.` is not); an optional exponent `e` or `E` with an optional sign and at
/// least one digit; nothing else (no hexadecimal, no `inf` or `nan`, no trailing characters).
/// Decimal to binary conversion rounds to nearest (std::from_chars). A magnitude that overflows
/// the type is NumberFault::TooLarge; one below the smallest subnormal reads as zero of the
/// token's sign.
/// @param type  NumberType::Float64, or NumberType::Float32 to round the double to the nearest
///              float32 (the value stays a double, exactly representable as float32)
/// @pre type is Float64 or Float32
ScannedNumber<double> scan_real(std::string_view token, NumberType type = NumberType::Float64);

/// Reads one whole token as an integer of `type`: the grammar of scan_real without a decimal
/// point or an exponent (a token that has one is NumberFault::NotAnInteger, so `1.0`, `1e2` and
/// `1.5` are refused where an integer is declared); a value outside the type's range is
/// NumberFault::OutOfRange (`-0` is 0 in every type). The value is returned as a 64-bit
/// integer of the type's signedness.
/// @pre type is one of the integer types
ScannedNumber<std::int64_t> scan_signed(std::string_view token, NumberType type);
/// @copydoc scan_signed
ScannedNumber<std::uint64_t> scan_unsigned(std::string_view token, NumberType type);

/// The one message for a refused token, e.g. "bad number '1e999': too large for a double",
/// "bad number '+-1': not a number", "bad number 'nan': not a number (inf and nan are not
/// accepted)". Control bytes of the token are shown as `\xNN` and a long token is cut short.
std::string bad_number_message(std::string_view token, NumberFault fault, NumberType type);

/// Error{BadInput, bad_number_message(...), location}; `location` names the file and line
/// ("cube.ply:14").
Error bad_number(std::string location, std::string_view token, NumberFault fault, NumberType type);

/// The same for a ScannedNumber that is not ok().
template <class T>
Error bad_number(std::string location, std::string_view token, const ScannedNumber<T>& scanned) {
  return bad_number(std::move(location), token, scanned.fault, scanned.type);
}

}  // namespace strata::io
