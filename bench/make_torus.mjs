// Writes a binary STL torus for the benchmarks: node bench/make_torus.mjs OUT.stl FACETS
// R = 40 mm, r = 15 mm, centred on the origin, axis z (110 x 110 x 30 mm).
import { writeBinaryStl } from './binary_stl.mjs';

const [out, facetsArg] = process.argv.slice(2);
if (!out) {
  console.error('usage: node bench/make_torus.mjs OUT.stl [FACETS]');
  process.exit(2);
}
const wanted = Number(facetsArg ?? 1_000_000);
// 2 * nu * nv facets, nu = 2 nv around the axis.
const nv = Math.max(3, Math.round(Math.sqrt(wanted / 4)));
const nu = 2 * nv;
const R = 40, r = 15;
const point = (u, v) => {
  // Indices wrap, so the seam closes exactly.
  const a = (2 * Math.PI * (u % nu)) / nu, b = (2 * Math.PI * (v % nv)) / nv;
  return [(R + r * Math.cos(b)) * Math.cos(a), (R + r * Math.cos(b)) * Math.sin(a), r * Math.sin(b)];
};
const count = 2 * nu * nv;
writeBinaryStl(out, 'strata benchmark torus', count, (facet) => {
  for (let u = 0; u < nu; ++u) {
    for (let v = 0; v < nv; ++v) {
      const p00 = point(u, v), p10 = point(u + 1, v), p01 = point(u, v + 1), p11 = point(u + 1, v + 1);
      facet(p00, p10, p11);
      facet(p00, p11, p01);
    }
  }
});
console.log(`${out}: ${count} facets`);
