#pragma once

#include <optional>
#include <string_view>

namespace strata::io {

/// The unit a model file's coordinates are in. strata works in millimetres (SPEC §2); a file in
/// another unit is converted as it is read.
enum class LengthUnit { Millimetre, Centimetre, Metre, Inch, Micrometre };

/// "mm", "cm", "m", "in", "um" (what `--units` takes), or nullopt for any other word.
std::optional<LengthUnit> parse_length_unit(std::string_view word);

/// The short name of parse_length_unit: "mm", "cm", "m", "in", "um".
std::string_view length_unit_name(LengthUnit unit);

/// Millimetres in one unit: 1, 10, 1000, 25.4 (exact, by definition of the inch), 0.001.
double millimetres_per(LengthUnit unit);

/// How read coordinates become millimetres: each is multiplied by millimetres_per(units) * scale
/// (one rounding in double); STL coordinates are then rounded to float32 again, since the format
/// is single precision, so that a model exported in metres reads as its millimetre export.
struct CoordinateScale {
  LengthUnit units = LengthUnit::Millimetre;
  double scale = 1.0;  ///< finite and > 0

  /// millimetres_per(units) * scale.
  double factor() const { return millimetres_per(units) * scale; }
};

}  // namespace strata::io
