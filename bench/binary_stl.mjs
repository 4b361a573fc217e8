// The binary STL writer of the benchmark mesh generators.
import { openSync, writeSync, closeSync } from 'node:fs';

/**
 * Writes `count` facets to `path` as binary STL, with `name` in the header and zero normals
 * (readers compute their own). `emit(facet)` calls facet(a, b, c) once a facet, each corner
 * an [x, y, z] array; a different number of facets is an error.
 */
export function writeBinaryStl(path, name, count, emit) {
  const buffer = Buffer.alloc(84 + 50 * count);
  buffer.write(name, 0, 'ascii');
  buffer.writeUInt32LE(count, 80);
  let at = 84;
  emit((a, b, c) => {
    at += 12;
    for (const p of [a, b, c]) for (const x of p) { buffer.writeFloatLE(x, at); at += 4; }
    at += 2;
  });
  if (at !== buffer.length) throw new Error(`wrote ${at} of ${buffer.length} bytes`);
  const fd = openSync(path, 'w');
  writeSync(fd, buffer);
  closeSync(fd);
}
