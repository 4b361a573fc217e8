// Writes a binary STL sphere for the benchmarks: node bench/make_sphere.mjs OUT.stl [FACETS]
// Radius 25 mm, centred on the origin (50 x 50 x 50 mm: 500 layers of 0.1 mm).
// A latitude-longitude sphere: nu meridians, nv bands, fans of nu facets at the poles,
// 2 nu (nv - 1) facets in all, nu = 2 nv.
import { writeBinaryStl } from './binary_stl.mjs';

const [out, facetsArg] = process.argv.slice(2);
if (!out) {
  console.error('usage: node bench/make_sphere.mjs OUT.stl [FACETS]');
  process.exit(2);
}
const wanted = Number(facetsArg ?? 200_000);
const nv = Math.max(3, Math.round(Math.sqrt(wanted / 4)));
const nu = 2 * nv;
const radius = 25;
const point = (u, v) => {
  // v = 0 and v = nv are the poles, shared by every meridian so the fans close exactly;
  // u wraps, so the seam closes exactly too.
  if (v === 0) return [0, 0, -radius];
  if (v === nv) return [0, 0, radius];
  const a = (2 * Math.PI * (u % nu)) / nu, b = Math.PI * (v / nv) - Math.PI / 2;
  return [radius * Math.cos(b) * Math.cos(a), radius * Math.cos(b) * Math.sin(a),
          radius * Math.sin(b)];
};
const count = 2 * nu * (nv - 1);
writeBinaryStl(out, 'strata benchmark sphere', count, (facet) => {
  // Counter-clockwise seen from outside, so the normals point out.
  for (let u = 0; u < nu; ++u) {
    for (let v = 0; v < nv; ++v) {
      const p00 = point(u, v), p10 = point(u + 1, v), p01 = point(u, v + 1), p11 = point(u + 1, v + 1);
      if (v !== 0) facet(p00, p10, p11);
      if (v !== nv - 1) facet(p00, p11, p01);
    }
  }
});
console.log(`${out}: ${count} facets`);
