// Writes a binary STL sand mould at metre scale: node tools/make_sand_mould.mjs OUT.stl [SEGMENTS]
//
// A 1800 x 1000 x 700 mm box of sand (millimetres, the minimum corner at the origin) holding
// six mould cavities (the castings' shapes) in two rows of three, a cylindrical core standing in
// each cavity, and closed channels through the sand between them: three along x and two along y,
// at other heights so that no two solids touch. Every shell is closed and consistently oriented:
// the box, the cores: normals out; the cavities and the channels (voids in the sand): normals
// in. At 0.1 mm that is a grid of 18000 x 10000 x 7000 cells (1.26 x 10^12).
// SEGMENTS (default 256) is the facet count around each cylinder.
import { writeBinaryStl } from '../bench/binary_stl.mjs';

const [out, segmentsArg] = process.argv.slice(2);
if (!out) {
  console.error('usage: node tools/make_sand_mould.mjs OUT.stl [SEGMENTS]');
  process.exit(2);
}
const segments = Number(segmentsArg ?? 256);
if (!Number.isInteger(segments) || segments < 3) {
  console.error(`make_sand_mould: SEGMENTS must be an integer >= 3, not '${segmentsArg}'`);
  process.exit(2);
}

const shells = [];  // each a list of facets [a, b, c], counter-clockwise seen from outside

// An axis-aligned box [x0, x1] x [y0, y1] x [z0, z1]: 12 facets.
function box(x0, y0, z0, x1, y1, z1) {
  const p = (i, j, k) => [i ? x1 : x0, j ? y1 : y0, k ? z1 : z0];
  const quad = (a, b, c, d) => [[a, b, c], [a, c, d]];  // a b c d counter-clockwise from outside
  return [
    ...quad(p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)),  // bottom, -z
    ...quad(p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)),  // top, +z
    ...quad(p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)),  // -y
    ...quad(p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)),  // +y
    ...quad(p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)),  // -x
    ...quad(p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)),  // +x
  ];
}

// A closed cylinder of radius r from `from` to `to` along one axis ('x', 'y' or 'z'), capped
// by fans around the axis' end points: 4 * segments facets.
function cylinder(axis, from, to, centre, r) {
  // (u, v): the two other axes, in the cyclic order that makes (u, v, axis) right-handed.
  const place = {
    x: (t, u, v) => [t, u, v],
    y: (t, u, v) => [v, t, u],
    z: (t, u, v) => [u, v, t],
  }[axis];
  const [cu, cv] = centre;
  const rim = (t, i) => {
    const a = (2 * Math.PI * (i % segments)) / segments;
    return place(t, cu + r * Math.cos(a), cv + r * Math.sin(a));
  };
  const facets = [];
  const c0 = place(from, cu, cv), c1 = place(to, cu, cv);
  for (let i = 0; i < segments; ++i) {
    const a0 = rim(from, i), b0 = rim(from, i + 1), a1 = rim(to, i), b1 = rim(to, i + 1);
    facets.push([a0, b0, b1], [a0, b1, a1]);  // the side
    facets.push([c0, b0, a0]);                // the cap at `from`, facing -axis
    facets.push([c1, a1, b1]);                // the cap at `to`, facing +axis
  }
  return facets;
}

const inward = (facets) => facets.map(([a, b, c]) => [a, c, b]);

shells.push(box(0, 0, 0, 1800, 1000, 700));
for (const [x0, x1] of [[100, 500], [700, 1100], [1300, 1700]]) {
  for (const [y0, y1] of [[130, 430], [570, 870]]) {
    shells.push(inward(box(x0, y0, 150, x1, y1, 550)));                            // cavity
    shells.push(cylinder('z', 200, 500, [(x0 + x1) / 2, (y0 + y1) / 2], 80));    // core
  }
}
// Channels along x at y = 500 (between the rows of cavities), along y at x = 600 and 1200
// (between the columns): their heights 60 mm apart, radius 20 mm, so none meets another.
for (const z of [180, 300, 420]) shells.push(inward(cylinder('x', 60, 1740, [500, z], 20)));
for (const x of [600, 1200]) {
  for (const z of [240, 360]) shells.push(inward(cylinder('y', 60, 940, [z, x], 20)));
}

const count = shells.reduce((n, s) => n + s.length, 0);
writeBinaryStl(out, 'strata sand mould 1800 x 1000 x 700 mm', count, (facet) => {
  for (const shell of shells) for (const [a, b, c] of shell) facet(a, b, c);
});
console.log(`${out}: ${count} facets, 1800 x 1000 x 700 mm`);
