// Writes a C++ source that holds a file's bytes, for the library to embed the built page:
//   node web/embed_cpp.mjs IN.html OUT.cpp [HEADER NAMESPACE FUNCTION]
// (default: view/view_template_internal.hpp, strata::view::detail, view_page_template).
// The bytes become string literals (printable ASCII as is, the rest as octal escapes), which
// compile faster than an array of numbers; each piece stays under the 65,536 characters that
// compilers are required to support in one literal, and the pieces are joined once at run time.
import { readFileSync, writeFileSync, renameSync } from 'node:fs';

const [input, output, header = 'view/view_template_internal.hpp', namespace = 'strata::view::detail',
  fn = 'view_page_template'] = process.argv.slice(2);
if (!input || !output) {
  console.error('usage: node web/embed_cpp.mjs IN.html OUT.cpp [HEADER NAMESPACE FUNCTION]');
  process.exit(2);
}
const bytes = readFileSync(input);
const PIECE_BYTES = 12_000; // at most 4 characters a byte: well under 65,536
const pieces = [];
let lines = [];
let line = '';
let inPiece = 0;
const endPiece = () => {
  if (line) lines.push(`"${line}"`);
  line = '';
  if (lines.length) pieces.push(lines.join('\n'));
  lines = [];
  inPiece = 0;
};
for (const b of bytes) {
  let piece;
  if (b === 0x22) piece = '\\"';
  else if (b === 0x5c) piece = '\\\\';
  else if (b === 0x0a) piece = '\\n';
  else if (b >= 0x20 && b < 0x7f && b !== 0x3f) piece = String.fromCharCode(b);
  else piece = '\\' + b.toString(8).padStart(3, '0');
  line += piece;
  if (line.length >= 100 || b === 0x0a) {
    lines.push(`"${line}"`);
    line = '';
  }
  if (++inPiece >= PIECE_BYTES) endPiece();
}
endPiece();
const source = `// Generated from ${input.split('/').pop()} by web/embed_cpp.mjs at build time; not edited.
#include <string>

#include "${header}"

namespace ${namespace} {

namespace {
// sizeof - 1 of each literal keeps any NUL byte of the file.
#define STRATA_PIECE(literal) std::string_view(literal, sizeof(literal) - 1)
const std::string_view kPieces[] = {
${pieces.map((p) => `STRATA_PIECE(\n${p})`).join(',\n')}};
#undef STRATA_PIECE
}  // namespace

std::string_view ${fn}() {
  static const std::string page = [] {
    std::string joined;
    for (std::string_view piece : kPieces) joined.append(piece);
    return joined;
  }();
  return page;
}

}  // namespace ${namespace}
`;
writeFileSync(output + '.tmp', source);
renameSync(output + '.tmp', output);
