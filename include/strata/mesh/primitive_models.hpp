#pragma once

#include <cstdint>

#include "strata/mesh/triangle_soup.hpp"
#include "strata/mesh/vec3.hpp"

/// Generators of closed, outward-oriented test and sample models, and exact transforms of soups.
///
/// Every generator returns a TriangleSoup whose triangles are oriented outward (right-hand rule:
/// the normal (b - a) x (c - a) points away from the solid), whose surface is closed (each
/// undirected edge is used by exactly two triangles, in opposite directions) and whose corners
/// are exactly shared: a vertex is computed once and copied into every triangle that uses it.
/// Coordinates are millimetres, rounded to float32 (then held as double) so that a generated soup
/// is bit-identical to its STL encoding read back. `stored_normals` is empty, `format` is
/// "generated". Invalid parameters (non-finite, non-positive sizes, too few segments) violate the
/// precondition and throw strata::InternalError through STRATA_ASSERT.
namespace strata::mesh {

/// Axis-aligned box [min, max], 12 triangles (two a face), 8 shared corners.
/// Volume: (max.x - min.x) (max.y - min.y) (max.z - min.z), exact for float32 corners.
/// @pre min < max on every axis, all finite.
TriangleSoup make_box(const Vec3& min, const Vec3& max);

/// Tetrahedron with corners a, b, c, d (4 triangles), oriented outward whatever the order of
/// the corners: when (b - a) . ((c - a) x (d - a)) < 0 the roles of b and c are swapped.
/// The defaults give the tetrahedron test shape of entity slicing as strata uses it: a
/// right-angled corner with 10 mm legs at the origin.
/// Volume: |(b - a) . ((c - a) x (d - a))| / 6 (1000/6 mm^3 for the defaults).
/// @pre the corners are not coplanar (the orientation determinant, in double, is not zero).
TriangleSoup make_tetrahedron(const Vec3& a = {0, 0, 0}, const Vec3& b = {10, 0, 0},
                              const Vec3& c = {0, 10, 0}, const Vec3& d = {0, 0, 10});

/// Annulus prism (a ring, the second test shape of entity slicing): axis z, base on z = 0, top on
/// z = height, centred on the origin. Both walls are regular `segments`-gons whose corners lie on
/// the circles of radius r_outer and r_inner (up to float32 rounding); corner k is at angle
/// 2 pi k / segments, computed by quadrant symmetry so that the corners at multiples of 90 degrees
/// are exact and, when segments % 4 == 0, a 90 degree rotation about z maps the corner set onto
/// itself exactly. 8 * segments triangles.
/// Volume of the polyhedron: height * (segments / 2) * sin(2 pi / segments) * (r_outer^2 -
/// r_inner^2); it falls short of the true ring, pi (r_outer^2 - r_inner^2) height, by the relative
/// amount 1 - sin(2 pi / n) / (2 pi / n) ~ (2 pi / n)^2 / 6 (4.0e-4 for n = 128).
/// @pre 0 < r_inner < r_outer, height > 0, segments >= 3.
TriangleSoup make_ring(double r_outer, double r_inner, double height, int segments);

/// Closed cylinder: axis z, base on z = 0, top on z = height, centred on the origin; the wall is
/// a regular `segments`-gon on the circle of radius `radius` (corners as in make_ring) and each
/// cap is a fan around its centre. 4 * segments triangles.
/// Volume: height * (segments / 2) * sin(2 pi / segments) * radius^2.
/// @pre radius > 0, height > 0, segments >= 3.
TriangleSoup make_cylinder(double radius, double height, int segments);

/// Icosphere centred on the origin: an icosahedron whose triangles are split `subdivisions` times
/// into four, every new corner pushed onto the sphere of radius `radius` (up to float32
/// rounding). 20 * 4^subdivisions triangles; it is convex and inscribed in the sphere.
/// Volume: below the ball's 4/3 pi r^3; since every face plane lies at distance
/// h_f = sqrt(r^2 - rho_f^2) from the centre (rho_f the face's circumradius), the polyhedron
/// contains the ball of radius min h_f and its volume is at least (min h_f / r)^3 of the ball's.
/// Relative deficit vs the ball: 3.4% at 2 subdivisions, 0.86% at 3, 0.22% at 4, 0.054% at 5.
/// @pre radius > 0, 0 <= subdivisions <= 7.
TriangleSoup make_sphere(double radius, int subdivisions);

/// The same soup moved by `offset` (each coordinate rounded to double once; exact when the sums
/// are representable, e.g. integer offsets on float32 coordinates of moderate size).
TriangleSoup translate_soup(const TriangleSoup& soup, const Vec3& offset);

/// The soup rotated by +90 degrees about the z axis: (x, y, z) -> (-y, x, z). Exact (only a
/// negation and a swap), orientation preserved; stored normals are rotated too.
TriangleSoup rotate_soup_z90(const TriangleSoup& soup);

/// The soup scaled about the origin by `factor`; exact when factor is a power of two and no
/// coordinate overflows or underflows. A negative factor would turn the solid inside out and is
/// not allowed. @pre factor > 0 and finite.
TriangleSoup scale_soup(const TriangleSoup& soup, double factor);

/// The same triangles in a shuffled order (Fisher-Yates driven by std::mt19937_64 seeded with
/// `seed`, so the permutation is the same on every platform). Stored normals move with their
/// triangles.
TriangleSoup shuffle_facets(const TriangleSoup& soup, std::uint64_t seed);

/// Every triangle's corners cycled (a, b, c) -> (b, c, a): same geometry and orientation, other
/// starting corner.
TriangleSoup rotate_corners(const TriangleSoup& soup);

/// Every triangle reversed, (a, b, c) -> (a, c, b), turning the solid inside out; stored normals
/// are negated.
TriangleSoup flip_orientation(const TriangleSoup& soup);

}  // namespace strata::mesh
