// Writes a C++ source that holds a file's bytes, for the library to embed the built page:
//   node web/embed_cpp.mjs IN.html OUT.cpp [HEADER NAMESPACE FUNCTION]
// (default: view/view_template_internal.hpp, strata::view::detail, view_page_template).
// The bytes become adjacent string literals (printable ASCII as is, the rest as octal escapes),
// which compile faster than an array of numbers.
import { readFileSync, writeFileSync, renameSync } from 'node:fs';

const [input, output, header = 'view/view_template_internal.hpp', namespace = 'strata::view::detail',
  fn = 'view_page_template'] = process.argv.slice(2);
if (!input || !output) {
  console.error('usage: node web/embed_cpp.mjs IN.html OUT.cpp [HEADER NAMESPACE FUNCTION]');
  process.exit(2);
}
const bytes = readFileSync(input);
const lines = [];
let line = '';
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
}
if (line) lines.push(`"${line}"`);
const source = `// Generated from ${input.split('/').pop()} by web/embed_cpp.mjs at build time; not edited.
#include "${header}"

namespace ${namespace} {

namespace {
constexpr char kPage[] =
${lines.join('\n')};
}  // namespace

std::string_view ${fn}() { return {kPage, sizeof(kPage) - 1}; }

}  // namespace ${namespace}
`;
writeFileSync(output + '.tmp', source);
renameSync(output + '.tmp', output);
