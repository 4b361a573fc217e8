#include "cli/units_options.hpp"

#include "cli/option_checks.hpp"

namespace strata::cli {

void add_units_options(CLI::App& command, UnitsCliOptions& o) {
  command
      .add_option("--units", o.units,
                  "Unit of the model file's coordinates (mm, cm, m, in, um); they are converted "
                  "to mm as they are read")
      ->default_val("mm")
      ->check(CLI::IsMember({"mm", "cm", "m", "in", "um"}));
  command
      .add_option("--scale", o.scale,
                  "Multiply the coordinates by this factor as they are read (after --units)")
      ->default_val(1.0)
      ->check(positive_real("scale factor"));
}

io::CoordinateScale to_coordinate_scale(const UnitsCliOptions& o) {
  return io::CoordinateScale{io::parse_length_unit(o.units).value_or(io::LengthUnit::Millimetre),
                             o.scale};
}

}  // namespace strata::cli
