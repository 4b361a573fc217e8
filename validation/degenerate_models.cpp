#include "degenerate_models.hpp"

#include <array>
#include <functional>
#include <utility>

#include "strata/mesh/primitive_models.hpp"

namespace strata::validation {

namespace {

// Every coordinate is rounded to float32 once, so that a model and its binary STL are the same.
double f32(double v) { return static_cast<double>(static_cast<float>(v)); }
Vec3 p3(double x, double y, double z) { return {f32(x), f32(y), f32(z)}; }

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Collects triangles; a vertex is a Vec3 value, so equal coordinates are shared exactly.
class Builder {
 public:
  void tri(const Vec3& a, const Vec3& b, const Vec3& c) { soup_.triangles.push_back({a, b, c}); }
  /// Two triangles (a, b, c) and (a, c, d): a planar quad with the orientation of a -> b -> c.
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    tri(a, b, c);
    tri(a, c, d);
  }
  /// A triangle of a convex solid, turned to face away from `inside`.
  void outward(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& inside) {
    if (dot(cross(sub(b, a), sub(c, a)), sub(a, inside)) < 0) {
      tri(a, c, b);
    } else {
      tri(a, b, c);
    }
  }
  void append(const TriangleSoup& other) {
    soup_.triangles.insert(soup_.triangles.end(), other.triangles.begin(), other.triangles.end());
  }
  TriangleSoup& soup() { return soup_; }
  TriangleSoup take() {
    soup_.format = "generated";
    return std::move(soup_);
  }

 private:
  TriangleSoup soup_;
};

TriangleSoup box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return mesh::make_box(p3(x0, y0, z0), p3(x1, y1, z1));
}

/// The union of the cells [xs[i], xs[i+1]] x [ys[j], ys[j+1]] x [zs[k], zs[k+1]] for which
/// `occupied(i, j, k)` holds: every face between an occupied and a free cell (or the outside),
/// as two triangles facing the free side. Cells that touch along an edge or at a corner only
/// give non-manifold edges and vertices, with exactly shared corners.
TriangleSoup lattice_solid(const std::vector<double>& xs, const std::vector<double>& ys,
                           const std::vector<double>& zs,
                           const std::function<bool(int, int, int)>& occupied) {
  const int nx = static_cast<int>(xs.size()) - 1;
  const int ny = static_cast<int>(ys.size()) - 1;
  const int nz = static_cast<int>(zs.size()) - 1;
  const auto occ = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz && occupied(i, j, k);
  };
  Builder b;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (!occ(i, j, k)) continue;
        const double x0 = xs[i], x1 = xs[i + 1], y0 = ys[j], y1 = ys[j + 1], z0 = zs[k],
                     z1 = zs[k + 1];
        if (!occ(i + 1, j, k))
          b.quad(p3(x1, y0, z0), p3(x1, y1, z0), p3(x1, y1, z1), p3(x1, y0, z1));
        if (!occ(i - 1, j, k))
          b.quad(p3(x0, y0, z0), p3(x0, y0, z1), p3(x0, y1, z1), p3(x0, y1, z0));
        if (!occ(i, j + 1, k))
          b.quad(p3(x0, y1, z0), p3(x0, y1, z1), p3(x1, y1, z1), p3(x1, y1, z0));
        if (!occ(i, j - 1, k))
          b.quad(p3(x0, y0, z0), p3(x1, y0, z0), p3(x1, y0, z1), p3(x0, y0, z1));
        if (!occ(i, j, k + 1))
          b.quad(p3(x0, y0, z1), p3(x1, y0, z1), p3(x1, y1, z1), p3(x0, y1, z1));
        if (!occ(i, j, k - 1))
          b.quad(p3(x0, y0, z0), p3(x0, y1, z0), p3(x1, y1, z0), p3(x1, y0, z0));
      }
    }
  }
  return b.take();
}

/// A box [0, sx] x [0, sy] x [0, sz] with its top face given by `top` (triangles in the plane
/// z = sz, counter-clockwise from above) instead of two triangles.
TriangleSoup box_with_top(double sx, double sy, double sz,
                          const std::vector<std::array<Vec3, 3>>& top) {
  Builder b;
  const Vec3 a0 = p3(0, 0, 0), b0 = p3(sx, 0, 0), c0 = p3(sx, sy, 0), d0 = p3(0, sy, 0);
  const Vec3 a1 = p3(0, 0, sz), b1 = p3(sx, 0, sz), c1 = p3(sx, sy, sz), d1 = p3(0, sy, sz);
  b.quad(a0, d0, c0, b0);  // bottom, facing -z
  b.quad(a0, b0, b1, a1);  // y = 0
  b.quad(b0, c0, c1, b1);  // x = sx
  b.quad(c0, d0, d1, c1);  // y = sy
  b.quad(d0, a0, a1, d1);  // x = 0
  for (const auto& t : top) b.tri(t[0], t[1], t[2]);
  return b.take();
}

TriangleSoup without_facets(TriangleSoup soup, std::size_t first, std::size_t count) {
  soup.triangles.erase(soup.triangles.begin() + static_cast<std::ptrdiff_t>(first),
                       soup.triangles.begin() + static_cast<std::ptrdiff_t>(first + count));
  return soup;
}

TriangleSoup joined(std::initializer_list<TriangleSoup> parts) {
  Builder b;
  for (const TriangleSoup& p : parts) b.append(p);
  return b.take();
}

}  // namespace

std::vector<GeneratedModel> degenerate_models() {
  std::vector<GeneratedModel> models;
  const auto add = [&](std::string name, std::string defects, TriangleSoup soup,
                       double cell = 1.0) {
    soup.format = "generated";
    models.push_back({std::move(name), std::move(defects), std::move(soup), cell});
  };

  // With the aligned grid (origin at the minimum corner, cell 1 mm) the cell centres, scanlines
  // and layer planes all lie at half-integer coordinates: the models put their features there.
  add("box-faces-on-ties",
      "facets on a layer plane (z = 3.5), a face through cell centres (x = 6.5), a face on a "
      "scanline (y = 4.5)",
      box(0, 0, 0, 6.5, 4.5, 3.5));

  add("staircase-on-ties",
      "steps: horizontal facets on layer planes, vertical facets through cell centres, edges "
      "on scanlines, vertices at cell centres; many coplanar facets",
      lattice_solid({0, 1.5, 3.5, 5.5, 7}, {0, 2.5, 4.5, 6}, {0, 1.5, 3.5, 5},
                    [](int i, int j, int k) { return i + j + k <= 3; }));

  {
    Builder b;
    const Vec3 bottom = p3(2.5, 2.5, 0), top = p3(2.5, 2.5, 5);
    const std::array<Vec3, 4> equator = {p3(0, 2.5, 2.5), p3(2.5, 0, 2.5), p3(5, 2.5, 2.5),
                                         p3(2.5, 5, 2.5)};
    const Vec3 inside = p3(2.5, 2.5, 2.5);
    for (int q = 0; q < 4; ++q) {
      b.outward(equator[q], equator[(q + 1) % 4], top, inside);
      b.outward(equator[q], equator[(q + 1) % 4], bottom, inside);
    }
    add("octahedron-on-ties",
        "equator vertices and edges in a layer plane (z = 2.5), on a scanline and at cell "
        "centres; axis through a column of cell centres",
        b.take());
  }

  add("tetrahedron-on-ties",
      "vertices at cell centres and on scanlines, a facet on the plane z = 0",
      mesh::make_tetrahedron(p3(0, 0, 0), p3(5.5, 0, 0), p3(0, 4.5, 0), p3(0, 0, 3.5)));

  {
    const Vec3 a = p3(0, 0, 3.5), bb = p3(6, 0, 3.5), c = p3(6, 5, 3.5), d = p3(0, 5, 3.5);
    const Vec3 m = p3(3.5, 2.5, 3.5);
    add("coplanar-fan-on-plane",
        "top of four coplanar facets lying in a layer plane, meeting at a vertex on a cell "
        "centre",
        box_with_top(6, 5, 3.5, {{a, bb, m}, {bb, c, m}, {c, d, m}, {d, a, m}}));
  }

  {
    Builder b;
    b.append(box(0, 0, 0, 3, 3, 5));
    const Vec3 s0 = p3(4, 0, 2.5), s1 = p3(7, 0, 2.5), s2 = p3(7, 3, 2.5), s3 = p3(4, 3, 2.5);
    b.quad(s0, s1, s2, s3);
    b.quad(s0, s3, s2, s1);
    add("double-sided-sheet-on-plane",
        "a zero-thickness square, both sides, lying in a layer plane beside a box (horizontal "
        "facets on the plane, winding 0 around it)",
        b.take());
  }

  {
    Builder b;
    b.append(box(0, 0, 0, 4, 4, 4));
    // Needle: a square pyramid 0.02 mm wide whose axis runs through the cell centres (6.5, 1.5).
    const Vec3 apex = p3(6.5, 1.5, 5);
    const std::array<Vec3, 4> base = {p3(6.49, 1.49, 0), p3(6.51, 1.49, 0), p3(6.51, 1.51, 0),
                                      p3(6.49, 1.51, 0)};
    const Vec3 inside = p3(6.5, 1.5, 0.5);
    for (int q = 0; q < 4; ++q) b.outward(base[q], base[(q + 1) % 4], apex, inside);
    b.outward(base[0], base[2], base[1], inside);
    b.outward(base[0], base[3], base[2], inside);
    // Sliver: a tetrahedron 0.0002 mm thick whose large facet lies in the scanline plane y = 6.5.
    const Vec3 t0 = p3(0, 6.5, 0), t1 = p3(5, 6.5, 0), t2 = p3(2.5, 6.5, 5),
               t3 = p3(2.5, 6.5002, 0.1);
    b.append(mesh::make_tetrahedron(t0, t1, t2, t3));
    add("needle-and-sliver",
        "a needle 0.02 mm wide along a column of cell centres; a sliver tetrahedron 0.0002 mm "
        "thick with a facet in a scanline plane",
        b.take());
  }

  {
    Builder b;
    const TriangleSoup cube = box(0, 0, 0, 4.5, 4.5, 4.5);
    b.append(cube);
    b.tri(p3(0, 0, 0), p3(0, 0, 0), p3(4.5, 0, 0));          // repeated corner
    b.tri(p3(0, 0, 4.5), p3(2.5, 0, 4.5), p3(4.5, 0, 4.5));  // three collinear corners
    b.tri(cube.triangles[0][0], cube.triangles[0][1], cube.triangles[0][2]);  // repeated
    b.tri(cube.triangles[2][0], cube.triangles[2][2], cube.triangles[2][1]);  // repeated, reversed
    add("zero-area-and-duplicate-facets",
        "2 zero-area facets (a repeated corner; collinear corners on an edge in a layer plane), "
        "a facet repeated, a facet repeated reversed",
        b.take());
  }

  {
    const Vec3 a = p3(0, 0, 3.5), bb = p3(4, 0, 3.5), c = p3(4, 4, 3.5), d = p3(0, 4, 3.5);
    const Vec3 m = p3(2.5, 0, 3.5);  // on the edge a-b, at a cell centre in a layer plane
    const std::vector<std::array<Vec3, 3>> top = {{a, m, d}, {m, bb, c}, {m, c, d}};
    add("t-junction-open",
        "T-junction: a top vertex in the middle of the front face's top edge (a crack of zero "
        "width; unbalanced edges), in a layer plane at a cell centre",
        box_with_top(4, 4, 3.5, top));
    TriangleSoup sealed = box_with_top(4, 4, 3.5, top);
    sealed.triangles.push_back({a, bb, m});
    add("t-junction-sealed", "the same T-junction sealed by a zero-area facet (balanced edges)",
        std::move(sealed));
  }

  add("boxes-sharing-an-edge",
      "two boxes sharing a vertical edge through a column of cell centres (non-manifold edge)",
      joined({box(0, 0, 0, 2.5, 2.5, 4), box(2.5, 2.5, 0, 5, 5, 4)}));

  add("boxes-sharing-a-vertex",
      "two boxes sharing one corner, at a cell centre in a layer plane (non-manifold vertex)",
      joined({box(0, 0, 0, 2.5, 2.5, 2.5), box(2.5, 2.5, 2.5, 5, 5, 5)}));

  add("checkerboard-cubes",
      "cubes on a 3D checkerboard: dozens of non-manifold edges and vertices on scanlines, "
      "layer planes and cell centres",
      lattice_solid({0, 1.5, 2.5, 3.5, 5}, {0, 1.5, 2.5, 3.5, 5}, {0, 1.5, 2.5, 3.5, 5},
                    [](int i, int j, int k) { return (i + j + k) % 2 == 0; }));

  add("open-top-box", "open mesh: the two top facets (in a layer plane) removed",
      without_facets(box(0, 0, 0, 5.5, 4.5, 3.5), 2, 2));

  add("open-side-box",
      "open mesh: the two facets of the face x = 5.5 removed (open chains in every layer)",
      without_facets(box(0, 0, 0, 5.5, 4.5, 3.5), 10, 2));

  add("overlapping-boxes",
      "two shells that overlap (winding 2 in the overlap: nonzero fills it, evenodd empties it)",
      joined({box(0, 0, 0, 4, 4, 4), box(2.5, 1.5, 0.5, 6.5, 5.5, 3.5)}));

  add("nested-boxes",
      "a shell inside another, both facing out (winding 2 inside: evenodd makes it hollow)",
      joined({box(0, 0, 0, 6, 6, 6), box(1.5, 1.5, 1.5, 4.5, 4.5, 4.5)}));

  add("hollow-box", "a cavity: an inverted shell inside a shell",
      joined({box(0, 0, 0, 6, 6, 6), mesh::flip_orientation(box(1.5, 1.5, 1.5, 4.5, 4.5, 4.5))}));

  add("inverted-box", "one shell turned inside out (winding -1)",
      mesh::flip_orientation(box(0, 0, 0, 4.5, 3.5, 2.5)));

  add("thin-features",
      "features thinner than a cell: a 0.06 mm wall around a plane of cell centres, a 0.05 mm "
      "wall between centres, a 0.04 mm pin on a column of centres, a 0.07 mm plate across a "
      "layer plane",
      joined({box(0, 0, 0, 8, 6, 1), box(2.47, 0, 1.2, 2.53, 6, 5), box(3.6, 0, 1.2, 3.65, 6, 5),
              box(5.48, 2.48, 1.2, 5.52, 2.52, 5), box(6, 0, 1.45, 8, 6, 1.52)}));

  {
    // A comb at machine coordinates: teeth 0.1 mm wide with 0.1 mm gaps, in float32 (whose
    // spacing there is 1.2e-4 mm). With cells of 0.04 mm every other tooth face lies on a plane
    // of cell centres, up to the float32 rounding.
    std::vector<double> xs;
    for (int n = 0; n <= 50; ++n) xs.push_back(1500.0 + 0.1 * n);
    add("machine-coordinates-comb",
        "a 5 mm comb at x = 1500 mm, y = 900 mm (float32): 25 teeth 0.1 mm wide, 0.1 mm gaps",
        lattice_solid(xs, {900, 902}, {0, 0.5, 1.5},
                      [](int i, int, int k) { return k == 0 || i % 2 == 0; }),
        0.04);
  }

  add("sphere", "none (a clean convex reference: icosphere, 1280 facets)",
      mesh::translate_soup(mesh::make_sphere(4, 3), {4, 4, 4}), 0.5);

  add("ring", "none (a clean reference with a hole: 64-gon ring)",
      mesh::translate_soup(mesh::make_ring(5, 3, 4, 64), {5, 5, 0}), 0.5);

  return models;
}

}  // namespace strata::validation
