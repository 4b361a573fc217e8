#include "strata/mesh/primitive_models.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "strata/core/error.hpp"

namespace strata::mesh {
namespace {

// Generated models are rounded to float32 once, so that writing them as STL and reading them
// back gives the same bits (SPEC §2: STL coordinates are float32).
double to_f32(double v) { return static_cast<double>(static_cast<float>(v)); }

Vec3 to_f32(const Vec3& p) { return {to_f32(p.x), to_f32(p.y), to_f32(p.z)}; }

bool finite(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Collects triangles over a shared vertex table, so that shared corners are the same bits.
class SoupBuilder {
 public:
  std::size_t add_vertex(const Vec3& p) {
    vertices_.push_back(to_f32(p));
    return vertices_.size() - 1;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) {
    soup_.triangles.push_back({vertices_[a], vertices_[b], vertices_[c]});
  }
  /// a, b, c, d counter-clockwise seen from outside the solid.
  void add_quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
  TriangleSoup finish() && {
    soup_.format = "generated";
    return std::move(soup_);
  }

 private:
  std::vector<Vec3> vertices_;
  TriangleSoup soup_;
};

/// Corner k of a regular n-gon on the unit circle, at angle 2 pi k / n. The angle is reduced to
/// the first octant with integer arithmetic, so multiples of 90 degrees are exact and corners a
/// quarter turn apart are exact rotations of each other.
std::pair<double, double> unit_circle_corner(int k, int n) {
  const long long m = 4LL * k;  // angle in quarter turns: m / n
  const long long quadrant = (m / n) % 4;
  const long long r = m % n;  // angle within the quadrant: (pi / 2) * r / n
  constexpr double kQuarter = std::numbers::pi / 2;
  double c = 1.0;
  double s = 0.0;
  if (2 * r <= n) {
    const double t = kQuarter * static_cast<double>(r) / n;
    c = std::cos(t);
    s = std::sin(t);
  } else {
    const double t = kQuarter * static_cast<double>(n - r) / n;
    c = std::sin(t);
    s = std::cos(t);
  }
  switch (quadrant) {
    case 0:
      return {c, s};
    case 1:
      return {-s, c};
    case 2:
      return {-c, -s};
    default:
      return {s, -c};
  }
}

void copy_with(const TriangleSoup& from, TriangleSoup& to) {
  to.diagnostics = from.diagnostics;
  to.format = from.format;
}

}  // namespace

TriangleSoup make_box(const Vec3& min, const Vec3& max) {
  STRATA_ASSERT(finite(min) && finite(max), "box corners must be finite");
  STRATA_ASSERT(min.x < max.x && min.y < max.y && min.z < max.z, "box min must be below max");
  SoupBuilder b;
  std::array<std::size_t, 8> v{};
  for (int i = 0; i < 8; ++i) {
    v[i] = b.add_vertex(
        {(i & 1) != 0 ? max.x : min.x, (i & 2) != 0 ? max.y : min.y, (i & 4) != 0 ? max.z : min.z});
  }
  b.add_quad(v[0], v[2], v[3], v[1]);  // z = min
  b.add_quad(v[4], v[5], v[7], v[6]);  // z = max
  b.add_quad(v[0], v[1], v[5], v[4]);  // y = min
  b.add_quad(v[2], v[6], v[7], v[3]);  // y = max
  b.add_quad(v[0], v[4], v[6], v[2]);  // x = min
  b.add_quad(v[1], v[3], v[7], v[5]);  // x = max
  return std::move(b).finish();
}

TriangleSoup make_tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  STRATA_ASSERT(finite(a) && finite(b) && finite(c) && finite(d),
                "tetrahedron corners must be finite");
  SoupBuilder s;
  const std::size_t ia = s.add_vertex(a);
  std::size_t ib = s.add_vertex(b);
  std::size_t ic = s.add_vertex(c);
  const std::size_t id = s.add_vertex(d);
  const Vec3 fa = to_f32(a);
  const double det = dot(sub(to_f32(b), fa), cross(sub(to_f32(c), fa), sub(to_f32(d), fa)));
  STRATA_ASSERT(det != 0.0, "tetrahedron corners must not be coplanar");
  if (det < 0) std::swap(ib, ic);
  // For a positively oriented (a, b, c, d) each face, seen from outside, runs counter-clockwise.
  s.add_triangle(ia, ic, ib);
  s.add_triangle(ia, ib, id);
  s.add_triangle(ia, id, ic);
  s.add_triangle(ib, ic, id);
  return std::move(s).finish();
}

TriangleSoup make_ring(double r_outer, double r_inner, double height, int segments) {
  STRATA_ASSERT(std::isfinite(r_outer) && std::isfinite(r_inner) && std::isfinite(height),
                "ring sizes must be finite");
  STRATA_ASSERT(0 < r_inner && r_inner < r_outer, "ring needs 0 < r_inner < r_outer");
  STRATA_ASSERT(height > 0, "ring height must be positive");
  STRATA_ASSERT(segments >= 3, "ring needs at least 3 segments");
  SoupBuilder b;
  const auto n = static_cast<std::size_t>(segments);
  // Per corner k: outer bottom, outer top, inner bottom, inner top.
  std::vector<std::array<std::size_t, 4>> corner(n);
  for (int k = 0; k < segments; ++k) {
    const auto [c, s] = unit_circle_corner(k, segments);
    auto& q = corner[static_cast<std::size_t>(k)];
    q[0] = b.add_vertex({r_outer * c, r_outer * s, 0.0});
    q[1] = b.add_vertex({r_outer * c, r_outer * s, height});
    q[2] = b.add_vertex({r_inner * c, r_inner * s, 0.0});
    q[3] = b.add_vertex({r_inner * c, r_inner * s, height});
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = corner[k];
    const auto& q = corner[(k + 1) % n];
    b.add_quad(p[0], q[0], q[1], p[1]);  // outer wall, facing away from the axis
    b.add_quad(p[2], p[3], q[3], q[2]);  // inner wall, facing the axis
    b.add_quad(p[1], q[1], q[3], p[3]);  // top, +z
    b.add_quad(p[0], p[2], q[2], q[0]);  // bottom, -z
  }
  return std::move(b).finish();
}

TriangleSoup make_cylinder(double radius, double height, int segments) {
  STRATA_ASSERT(std::isfinite(radius) && std::isfinite(height), "cylinder sizes must be finite");
  STRATA_ASSERT(radius > 0 && height > 0, "cylinder radius and height must be positive");
  STRATA_ASSERT(segments >= 3, "cylinder needs at least 3 segments");
  SoupBuilder b;
  const auto n = static_cast<std::size_t>(segments);
  const std::size_t bottom_centre = b.add_vertex({0.0, 0.0, 0.0});
  const std::size_t top_centre = b.add_vertex({0.0, 0.0, height});
  std::vector<std::array<std::size_t, 2>> corner(n);  // bottom, top
  for (int k = 0; k < segments; ++k) {
    const auto [c, s] = unit_circle_corner(k, segments);
    auto& q = corner[static_cast<std::size_t>(k)];
    q[0] = b.add_vertex({radius * c, radius * s, 0.0});
    q[1] = b.add_vertex({radius * c, radius * s, height});
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = corner[k];
    const auto& q = corner[(k + 1) % n];
    b.add_quad(p[0], q[0], q[1], p[1]);
    b.add_triangle(top_centre, p[1], q[1]);
    b.add_triangle(bottom_centre, q[0], p[0]);
  }
  return std::move(b).finish();
}

TriangleSoup make_sphere(double radius, int subdivisions) {
  STRATA_ASSERT(std::isfinite(radius) && radius > 0, "sphere radius must be positive");
  STRATA_ASSERT(subdivisions >= 0 && subdivisions <= 7, "sphere subdivisions must be in [0, 7]");
  // Unit-sphere corners in double; rounded to float32 only once, when scaled at the end.
  const double phi = std::numbers::phi;
  std::vector<Vec3> unit = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                            {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                            {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  const auto normalised = [](const Vec3& p) {
    const double len = std::sqrt(dot(p, p));
    return Vec3{p.x / len, p.y / len, p.z / len};
  };
  for (auto& p : unit) p = normalised(p);
  std::vector<std::array<std::size_t, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  // The icosahedron is convex and centred on the origin: a face is outward when its normal
  // points away from the centre.
  for (auto& f : faces) {
    const Vec3 n = cross(sub(unit[f[1]], unit[f[0]]), sub(unit[f[2]], unit[f[0]]));
    if (dot(n, unit[f[0]]) < 0) std::swap(f[1], f[2]);
  }
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    const auto mid = [&](std::size_t i, std::size_t j) {
      const auto key = i < j ? std::pair{i, j} : std::pair{j, i};
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const Vec3& a = unit[i];
      const Vec3& b = unit[j];
      unit.push_back(normalised({a.x + b.x, a.y + b.y, a.z + b.z}));
      midpoint.emplace(key, unit.size() - 1);
      return unit.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const std::size_t ab = mid(f[0], f[1]);
      const std::size_t bc = mid(f[1], f[2]);
      const std::size_t ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  SoupBuilder b;
  for (const auto& p : unit) b.add_vertex({radius * p.x, radius * p.y, radius * p.z});
  for (const auto& f : faces) b.add_triangle(f[0], f[1], f[2]);
  return std::move(b).finish();
}

TriangleSoup translate_soup(const TriangleSoup& soup, const Vec3& offset) {
  TriangleSoup out;
  copy_with(soup, out);
  out.stored_normals = soup.stored_normals;
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    auto& moved = out.triangles.emplace_back();
    for (int c = 0; c < 3; ++c) {
      moved[c] = {t[c].x + offset.x, t[c].y + offset.y, t[c].z + offset.z};
    }
  }
  return out;
}

TriangleSoup rotate_soup_z90(const TriangleSoup& soup) {
  const auto rotate = [](const Vec3& p) { return Vec3{-p.y, p.x, p.z}; };
  TriangleSoup out;
  copy_with(soup, out);
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    out.triangles.push_back({rotate(t[0]), rotate(t[1]), rotate(t[2])});
  }
  out.stored_normals.reserve(soup.stored_normals.size());
  for (const auto& n : soup.stored_normals) out.stored_normals.push_back(rotate(n));
  return out;
}

TriangleSoup scale_soup(const TriangleSoup& soup, double factor) {
  STRATA_ASSERT(std::isfinite(factor) && factor > 0, "scale factor must be positive");
  TriangleSoup out;
  copy_with(soup, out);
  out.stored_normals = soup.stored_normals;
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    auto& scaled = out.triangles.emplace_back();
    for (int c = 0; c < 3; ++c) scaled[c] = {t[c].x * factor, t[c].y * factor, t[c].z * factor};
  }
  return out;
}

TriangleSoup shuffle_facets(const TriangleSoup& soup, std::uint64_t seed) {
  const std::size_t n = soup.triangles.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  // std::shuffle's algorithm is unspecified; this Fisher-Yates on mt19937_64 (whose output the
  // standard fixes) gives the same order everywhere. The modulo bias is irrelevant for tests.
  std::mt19937_64 rng(seed);
  for (std::size_t i = n; i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(rng() % i);
    std::swap(order[i - 1], order[j]);
  }
  const bool has_normals = soup.stored_normals.size() == n;
  TriangleSoup out;
  copy_with(soup, out);
  out.triangles.reserve(n);
  if (has_normals) out.stored_normals.reserve(n);
  for (const std::size_t i : order) {
    out.triangles.push_back(soup.triangles[i]);
    if (has_normals) out.stored_normals.push_back(soup.stored_normals[i]);
  }
  return out;
}

TriangleSoup rotate_corners(const TriangleSoup& soup) {
  TriangleSoup out;
  copy_with(soup, out);
  out.stored_normals = soup.stored_normals;
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) out.triangles.push_back({t[1], t[2], t[0]});
  return out;
}

TriangleSoup flip_orientation(const TriangleSoup& soup) {
  TriangleSoup out;
  copy_with(soup, out);
  out.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) out.triangles.push_back({t[0], t[2], t[1]});
  out.stored_normals.reserve(soup.stored_normals.size());
  for (const auto& n : soup.stored_normals) out.stored_normals.push_back({-n.x, -n.y, -n.z});
  return out;
}

}  // namespace strata::mesh
