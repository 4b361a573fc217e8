#include "diagnose/exact_geometry.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gmpxx.h>
#include <mpfr.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/double_parts.hpp"
#include "core/huge_pages.hpp"
#include "diagnose/fixed_width_integer.hpp"
#include "strata/core/error.hpp"

namespace strata::diagnose::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 to_point(const Vec3& p) { return {p.x, p.y, p.z}; }

mpq_class exact_det(const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& c) {
  const mpq_class ux = mpq_class(b.x) - a.x, uy = mpq_class(b.y) - a.y, uz = mpq_class(b.z) - a.z;
  const mpq_class vx = mpq_class(c.x) - a.x, vy = mpq_class(c.y) - a.y, vz = mpq_class(c.z) - a.z;
  return n.x * (uy * vz - uz * vy) + n.y * (uz * vx - ux * vz) + n.z * (ux * vy - uy * vx);
}

/// A double as mantissa * 2^exponent with an odd (or zero) integer mantissa.
struct Dyadic {
  std::int64_t mantissa = 0;
  int exponent = 0;
};

/// @pre x finite. Read from the double's bits: frexp and ldexp are calls into the C library, and
/// a million facets' vertices make a million and a half coordinates.
Dyadic to_dyadic(double x) {
  if (x == 0.0) return {};
  const DoubleParts parts = split_double(x);
  const int zeros = std::countr_zero(parts.mantissa);
  // Exact: the low bits are zero.
  const auto mantissa = static_cast<std::int64_t>(parts.mantissa >> zeros);
  return {parts.negative ? -mantissa : mantissa, parts.exponent + zeros};
}

std::array<Dyadic, 3> to_dyadic(const Vec3& p) {
  return {to_dyadic(p.x), to_dyadic(p.y), to_dyadic(p.z)};
}

double round_to_double(const mpz_class& sum, int scale_exponent) {
  // value = sum * 2^scale_exponent / 6, rounded once.
  mpq_class q(sum, 6);
  q.canonicalize();
  if (scale_exponent >= 0) {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(scale_exponent));
  } else {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-scale_exponent));
  }
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

/// A coordinate as an integer over the common unit 2^min_exponent: magnitude 2^shift, with its
/// sign; the magnitude is the double's odd mantissa, below 2^53.
struct ScaledCoordinate {
  std::uint64_t magnitude = 0;
  std::uint32_t shift = 0;
  bool negative = false;
};

// A facet's determinant is six products of three coordinates, each under 2^(3 w) for coordinates
// of w bits on the common unit; their sum over 2^32 facets, with its sign, takes 3 w + 36 bits.
constexpr int kSumMarginBits = 36;

/// The sum of every group's determinants a · (b x c), on integers of N limbs: each product of
/// three coordinates is three limbs (their mantissas) shifted into place, so the work does not
/// grow with how far apart the coordinates' exponents are.
/// @pre 3 w + kSumMarginBits <= 64 N for coordinates of w bits on the common unit.
template <std::size_t N>
std::vector<mpz_class> sum_determinants(const IndexedMesh& mesh, int min_exponent,
                                        const std::vector<std::uint32_t>& group_of_facet,
                                        std::size_t num_groups, std::size_t parts) {
  const std::size_t nv = mesh.vertices.size();
  // Every entry is written by the threads, zeros too: the array is not zeroed on one thread
  // first (24 MB for a million facets).
  const auto coord = std::make_unique_for_overwrite<ScaledCoordinate[]>(3 * nv);
  advise_huge_pages(coord.get(), 3 * nv * sizeof(ScaledCoordinate));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v < range.end(); ++v) {
      const std::array<Dyadic, 3> p = to_dyadic(mesh.vertices[v]);
      for (std::size_t k = 0; k < 3; ++k) {
        coord[3 * v + k] =
            p[k].mantissa == 0
                ? ScaledCoordinate{}
                : ScaledCoordinate{static_cast<std::uint64_t>(std::llabs(p[k].mantissa)),
                                   static_cast<std::uint32_t>(p[k].exponent - min_exponent),
                                   p[k].mantissa < 0};
      }
    }
  });
  const std::size_t nf = mesh.triangles.size();
  std::vector<std::vector<Limbs<N>>> part_sums(parts, std::vector<Limbs<N>>(num_groups));
  tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
    std::vector<Limbs<N>>& sums = part_sums[part];
    const std::size_t begin = nf * part / parts;
    const std::size_t end = nf * (part + 1) / parts;
    if (begin == end) return;
    // A run of facets of one group is summed apart, and added to the group's sum when it ends:
    // a group's sum stays N limbs, however many groups (a soup of loose facets makes a million).
    ShiftedProductSum<N> run;
    std::uint32_t run_group = group_of_facet[begin];
    for (std::size_t f = begin; f < end; ++f) {
      if (group_of_facet[f] != run_group) {
        add_to(sums[run_group], run.total());
        run = {};
        run_group = group_of_facet[f];
      }
      const auto& t = mesh.triangles[f];
      const ScaledCoordinate* a = &coord[3 * static_cast<std::size_t>(t[0])];
      const ScaledCoordinate* b = &coord[3 * static_cast<std::size_t>(t[1])];
      const ScaledCoordinate* c = &coord[3 * static_cast<std::size_t>(t[2])];
      const auto add_term = [&run](const ScaledCoordinate& x, const ScaledCoordinate& y,
                                   const ScaledCoordinate& z, bool minus) {
        run.add(multiply(x.magnitude, y.magnitude, z.magnitude), x.shift + y.shift + z.shift,
                (x.negative != y.negative) != (z.negative != minus));
      };
      // a · (b x c), term by term.
      add_term(a[0], b[1], c[2], false);
      add_term(a[0], b[2], c[1], true);
      add_term(a[1], b[2], c[0], false);
      add_term(a[1], b[0], c[2], true);
      add_term(a[2], b[0], c[1], false);
      add_term(a[2], b[1], c[0], true);
    }
    add_to(sums[run_group], run.total());
  });
  std::vector<mpz_class> out(num_groups);
  for (std::size_t g = 0; g < num_groups; ++g) {
    Limbs<N> total{};
    for (std::size_t part = 0; part < parts; ++part) add_to(total, part_sums[part][g]);
    const SignedLimbs<N> v = sign_and_magnitude(total);
    mpz_import(out[g].get_mpz_t(), N, -1, sizeof(std::uint64_t), 0, 0, v.magnitude.data());
    if (v.negative) out[g] = -out[g];
  }
  return out;
}

/// sum_determinants on GMP's integers, for coordinates of any width.
std::vector<mpz_class> sum_determinants_gmp(const IndexedMesh& mesh, int min_exponent,
                                            const std::vector<std::uint32_t>& group_of_facet,
                                            std::size_t num_groups, std::size_t parts) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<mpz_class> coord(3 * nv);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v < range.end(); ++v) {
      const std::array<Dyadic, 3> p = to_dyadic(mesh.vertices[v]);
      for (std::size_t k = 0; k < 3; ++k) {
        if (p[k].mantissa == 0) continue;
        mpz_class& c = coord[3 * v + k];
        c = static_cast<long>(p[k].mantissa);
        mpz_mul_2exp(c.get_mpz_t(), c.get_mpz_t(),
                     static_cast<mp_bitcnt_t>(p[k].exponent - min_exponent));
      }
    }
  });
  const std::size_t nf = mesh.triangles.size();
  std::vector<std::vector<mpz_class>> part_sums(parts, std::vector<mpz_class>(num_groups));
  tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
    std::vector<mpz_class>& sums = part_sums[part];
    mpz_class minor, det;
    for (std::size_t f = nf * part / parts; f < nf * (part + 1) / parts; ++f) {
      const auto& t = mesh.triangles[f];
      const mpz_class* a = &coord[3 * static_cast<std::size_t>(t[0])];
      const mpz_class* b = &coord[3 * static_cast<std::size_t>(t[1])];
      const mpz_class* c = &coord[3 * static_cast<std::size_t>(t[2])];
      // det = a · (b x c)
      mpz_mul(minor.get_mpz_t(), b[1].get_mpz_t(), c[2].get_mpz_t());
      mpz_submul(minor.get_mpz_t(), b[2].get_mpz_t(), c[1].get_mpz_t());
      mpz_mul(det.get_mpz_t(), a[0].get_mpz_t(), minor.get_mpz_t());
      mpz_mul(minor.get_mpz_t(), b[2].get_mpz_t(), c[0].get_mpz_t());
      mpz_submul(minor.get_mpz_t(), b[0].get_mpz_t(), c[2].get_mpz_t());
      mpz_addmul(det.get_mpz_t(), a[1].get_mpz_t(), minor.get_mpz_t());
      mpz_mul(minor.get_mpz_t(), b[0].get_mpz_t(), c[1].get_mpz_t());
      mpz_submul(minor.get_mpz_t(), b[1].get_mpz_t(), c[0].get_mpz_t());
      mpz_addmul(det.get_mpz_t(), a[2].get_mpz_t(), minor.get_mpz_t());
      sums[group_of_facet[f]] += det;
    }
  });
  std::vector<mpz_class>& sums = part_sums[0];
  for (std::size_t part = 1; part < parts; ++part) {
    for (std::size_t g = 0; g < num_groups; ++g) sums[g] += part_sums[part][g];
  }
  return std::move(sums);
}

}  // namespace

bool is_collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return CGAL::collinear(to_point(a), to_point(b), to_point(c));
}

int normal_agreement_sign(const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Filter: each of the six products n_i u_j v_k carries a relative error of a few ulps (the
  // differences u = b - a, v = c - a are rounded once); 1e-14 of their absolute sum bounds the
  // error of the sum with a wide margin. Ties and tiny magnitudes go to exact rationals.
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double d =
      n.x * (uy * vz - uz * vy) + n.y * (uz * vx - ux * vz) + n.z * (ux * vy - uy * vx);
  const double bound = std::abs(n.x) * (std::abs(uy * vz) + std::abs(uz * vy)) +
                       std::abs(n.y) * (std::abs(uz * vx) + std::abs(ux * vz)) +
                       std::abs(n.z) * (std::abs(ux * vy) + std::abs(uy * vx));
  if (std::isfinite(d) && std::isfinite(bound) && bound > 1e-200 && std::abs(d) > 1e-14 * bound) {
    return d > 0 ? 1 : -1;
  }
  return sgn(exact_det(n, a, b, c));
}

ExactVolumes exact_signed_volumes(const IndexedMesh& mesh,
                                  const std::vector<std::uint32_t>& group_of_facet,
                                  std::size_t num_groups) {
  STRATA_ASSERT(group_of_facet.size() == mesh.triangles.size(), "one group per facet");
  // All coordinates become integers times one common power of two, so the determinants are
  // integer products and the sums need no gcd: exact and fast. The power is the lowest bit of
  // any non-zero coordinate; the highest bit sets how wide the integers are.
  struct BitSpan {
    int lowest = INT_MAX;
    int above_highest = INT_MIN;
  };
  const BitSpan span = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.vertices.size(), 4096), BitSpan{},
      [&](const auto& range, BitSpan found) {
        for (std::size_t v = range.begin(); v < range.end(); ++v) {
          for (const Dyadic& d : to_dyadic(mesh.vertices[v])) {
            if (d.mantissa == 0) continue;
            const auto width = static_cast<int>(
                std::bit_width(static_cast<std::uint64_t>(std::llabs(d.mantissa))));
            found.lowest = std::min(found.lowest, d.exponent);
            found.above_highest = std::max(found.above_highest, d.exponent + width);
          }
        }
        return found;
      },
      [](const BitSpan& a, const BitSpan& b) {
        return BitSpan{std::min(a.lowest, b.lowest), std::max(a.above_highest, b.above_highest)};
      });
  const int min_exponent = span.lowest;
  ExactVolumes result;
  result.by_group_mm3.assign(num_groups, 0.0);
  if (min_exponent == INT_MAX) return result;  // every coordinate is zero

  // The facets are cut into parts summed on their own; integer sums do not depend on the
  // order. A part holds a sum for every group, so many groups (a soup of loose facets) make
  // one part.
  const std::size_t nf = mesh.triangles.size();
  constexpr std::size_t kMaxParts = 8;
  constexpr std::size_t kMinFacetsAPart = 16384;
  const std::size_t parts =
      num_groups > 64 ? 1 : std::clamp<std::size_t>(nf / kMinFacetsAPart, 1, kMaxParts);

  // The scaled coordinates' widths pick the arithmetic: four or six limbs while the sum over
  // every facet fits them (the usual case: a model's coordinates span a few powers of ten, or
  // some tens of powers of two more where a coordinate is nearly zero), GMP's integers otherwise.
  const int widest = span.above_highest - min_exponent;
  std::vector<mpz_class> sums;
  const int sum_bits = 3 * widest + kSumMarginBits;
  if (sum_bits <= 4 * 64) {
    sums = sum_determinants<4>(mesh, min_exponent, group_of_facet, num_groups, parts);
  } else if (sum_bits <= 6 * 64) {
    sums = sum_determinants<6>(mesh, min_exponent, group_of_facet, num_groups, parts);
  } else {
    sums = sum_determinants_gmp(mesh, min_exponent, group_of_facet, num_groups, parts);
  }
  mpz_class total;
  const int scale = 3 * min_exponent;
  for (std::size_t g = 0; g < num_groups; ++g) {
    total += sums[g];
    result.by_group_mm3[g] = round_to_double(sums[g], scale);
  }
  result.total_mm3 = round_to_double(total, scale);
  return result;
}

}  // namespace strata::diagnose::detail
