#include "strata/slice/slice_options.hpp"

namespace strata {

const char* to_string(FillRule rule) {
  switch (rule) {
    case FillRule::NonZero:
      return "nonzero";
    case FillRule::EvenOdd:
      return "evenodd";
    case FillRule::Winding:
      return "winding";
  }
  return "?";
}

const char* to_string(ShellMode mode) {
  switch (mode) {
    case ShellMode::Distance:
      return "distance";
    case ShellMode::Layers:
      return "layers";
  }
  return "?";
}

}  // namespace strata
