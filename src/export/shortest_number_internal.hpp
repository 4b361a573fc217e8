#pragma once

namespace strata::io::detail {

/// The room write_shortest needs: the longest text it writes, "-2.2250738585072014e-308" (24
/// characters), and as many again, which it may write past the text's end.
inline constexpr int kShortestNumberChars = 48;

/// Writes a double in the shortest form that reads back to the same bits, exactly the text of
/// fmt::format("{}", v) (the number grammar of every text strata writes); returns the end.
/// The digits are fmt's own (Dragonbox); their layout is written here, without fmt's general
/// formatting machinery, which took most of the time of writing a CLI file.
char* write_shortest(char* out, double v);

}  // namespace strata::io::detail
