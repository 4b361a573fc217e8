#include "diagnose/exact_geometry.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gmpxx.h>
#include <mpfr.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

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

Dyadic to_dyadic(double x) {
  if (x == 0.0) return {};
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m * 2^e, 0.5 <= |m| < 1
  auto mantissa = static_cast<std::int64_t>(std::ldexp(m, 53));
  int exponent = e - 53;
  const int zeros = std::countr_zero(static_cast<std::uint64_t>(std::llabs(mantissa)));
  mantissa >>= zeros;  // exact: the low bits are zero
  exponent += zeros;
  return {mantissa, exponent};
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

// Coordinates as integers over 2^min_exponent. With at most 62 bits, a minor (a difference of
// two products) takes under 2^125 and a facet's determinant under 2^189: one limb a coordinate,
// two a minor, four a sum over 2^32 facets. With at most 100 bits: two, four and seven.
constexpr int kMaxBitsOneLimb = 62;
constexpr int kMaxBitsTwoLimbs = 100;

template <std::size_t L>
SignedLimbs<L> scaled_coordinate(const Dyadic& d, int min_exponent) {
  SignedLimbs<L> out;
  out.negative = d.mantissa < 0;
  const std::uint64_t m = static_cast<std::uint64_t>(std::llabs(d.mantissa));
  const int shift = d.exponent - min_exponent;
  const int limb = shift / 64;
  const int bit = shift % 64;
  out.magnitude[static_cast<std::size_t>(limb)] = m << bit;
  if (bit > 0 && static_cast<std::size_t>(limb) + 1 < L) {
    out.magnitude[static_cast<std::size_t>(limb) + 1] = m >> (64 - bit);
  }
  return out;
}

/// The sum of every group's determinants a · (b x c), on integers of L limbs a coordinate.
/// @pre every scaled coordinate fits the bounds above for L.
template <std::size_t L>
std::vector<mpz_class> sum_determinants(const IndexedMesh& mesh, const std::vector<Dyadic>& dyadic,
                                        int min_exponent,
                                        const std::vector<std::uint32_t>& group_of_facet,
                                        std::size_t num_groups, std::size_t parts) {
  constexpr std::size_t kSum = 3 * L + 1;
  std::vector<SignedLimbs<L>> coord(dyadic.size());
  for (std::size_t i = 0; i < dyadic.size(); ++i) {
    if (dyadic[i].mantissa != 0) coord[i] = scaled_coordinate<L>(dyadic[i], min_exponent);
  }
  const std::size_t nf = mesh.triangles.size();
  std::vector<std::vector<Limbs<kSum>>> part_sums(parts, std::vector<Limbs<kSum>>(num_groups));
  tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
    std::vector<Limbs<kSum>>& sums = part_sums[part];
    for (std::size_t f = nf * part / parts; f < nf * (part + 1) / parts; ++f) {
      const auto& t = mesh.triangles[f];
      const SignedLimbs<L>* a = &coord[3 * static_cast<std::size_t>(t[0])];
      const SignedLimbs<L>* b = &coord[3 * static_cast<std::size_t>(t[1])];
      const SignedLimbs<L>* c = &coord[3 * static_cast<std::size_t>(t[2])];
      Limbs<kSum>& sum = sums[group_of_facet[f]];
      add_product(sum, a[0], cross_difference(b[1], c[2], b[2], c[1]));
      add_product(sum, a[1], cross_difference(b[2], c[0], b[0], c[2]));
      add_product(sum, a[2], cross_difference(b[0], c[1], b[1], c[0]));
    }
  });
  std::vector<mpz_class> out(num_groups);
  for (std::size_t g = 0; g < num_groups; ++g) {
    Limbs<kSum> total{};
    for (std::size_t part = 0; part < parts; ++part) add_to(total, part_sums[part][g]);
    const SignedLimbs<kSum> v = sign_and_magnitude(total);
    mpz_import(out[g].get_mpz_t(), kSum, -1, sizeof(std::uint64_t), 0, 0, v.magnitude.data());
    if (v.negative) out[g] = -out[g];
  }
  return out;
}

/// sum_determinants on GMP's integers, for coordinates of any width.
std::vector<mpz_class> sum_determinants_gmp(const IndexedMesh& mesh,
                                            const std::vector<Dyadic>& dyadic, int min_exponent,
                                            const std::vector<std::uint32_t>& group_of_facet,
                                            std::size_t num_groups, std::size_t parts) {
  const std::size_t nv3 = dyadic.size();
  std::vector<mpz_class> coord(nv3);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv3, 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const Dyadic& d = dyadic[i];
      if (d.mantissa == 0) continue;
      coord[i] = static_cast<long>(d.mantissa);
      mpz_mul_2exp(coord[i].get_mpz_t(), coord[i].get_mpz_t(),
                   static_cast<mp_bitcnt_t>(d.exponent - min_exponent));
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
  // integer products and the sums need no gcd: exact and fast.
  const std::size_t nv = mesh.vertices.size();
  std::vector<Dyadic> dyadic(3 * nv);
  int min_exponent = INT_MAX;
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3& p = mesh.vertices[i];
    dyadic[3 * i] = to_dyadic(p.x);
    dyadic[3 * i + 1] = to_dyadic(p.y);
    dyadic[3 * i + 2] = to_dyadic(p.z);
    for (int k = 0; k < 3; ++k) {
      if (dyadic[3 * i + k].mantissa != 0) {
        min_exponent = std::min(min_exponent, dyadic[3 * i + k].exponent);
      }
    }
  }
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

  // The scaled coordinates' widths pick the arithmetic: one or two limbs while the products of
  // three and their sum over every facet fit in a few limbs (the usual case: a model's
  // coordinates span a few powers of ten), GMP's integers otherwise.
  int widest = 0;
  for (const Dyadic& d : dyadic) {
    if (d.mantissa == 0) continue;
    const int bits =
        static_cast<int>(std::bit_width(static_cast<std::uint64_t>(std::llabs(d.mantissa)))) +
        (d.exponent - min_exponent);
    widest = std::max(widest, bits);
  }
  std::vector<mpz_class> sums;
  if (widest <= kMaxBitsOneLimb) {
    sums = sum_determinants<1>(mesh, dyadic, min_exponent, group_of_facet, num_groups, parts);
  } else if (widest <= kMaxBitsTwoLimbs) {
    sums = sum_determinants<2>(mesh, dyadic, min_exponent, group_of_facet, num_groups, parts);
  } else {
    sums = sum_determinants_gmp(mesh, dyadic, min_exponent, group_of_facet, num_groups, parts);
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
