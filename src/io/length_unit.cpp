#include "strata/io/length_unit.hpp"

namespace strata::io {

std::optional<LengthUnit> parse_length_unit(std::string_view word) {
  if (word == "mm") return LengthUnit::Millimetre;
  if (word == "cm") return LengthUnit::Centimetre;
  if (word == "m") return LengthUnit::Metre;
  if (word == "in") return LengthUnit::Inch;
  if (word == "um") return LengthUnit::Micrometre;
  return std::nullopt;
}

std::string_view length_unit_name(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return "mm";
    case LengthUnit::Centimetre:
      return "cm";
    case LengthUnit::Metre:
      return "m";
    case LengthUnit::Inch:
      return "in";
    case LengthUnit::Micrometre:
      return "um";
  }
  return "mm";
}

double millimetres_per(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return 1.0;
    case LengthUnit::Centimetre:
      return 10.0;
    case LengthUnit::Metre:
      return 1000.0;
    case LengthUnit::Inch:
      return 25.4;
    case LengthUnit::Micrometre:
      return 0.001;
  }
  return 1.0;
}

}  // namespace strata::io
