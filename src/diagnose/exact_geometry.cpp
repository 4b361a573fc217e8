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
#include <optional>
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
    std::uint32_t run_group = kNoGroup;  // the run is empty until a facet in a group comes
    for (std::size_t f = begin; f < end; ++f) {
      if (group_of_facet[f] == kNoGroup) continue;
      if (group_of_facet[f] != run_group) {
        if (run_group != kNoGroup) add_to(sums[run_group], run.total());
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
    if (run_group != kNoGroup) add_to(sums[run_group], run.total());
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
      if (group_of_facet[f] == kNoGroup) continue;
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

// ---- The floating-point filter
//
// A facet's determinant a · (b x c) is evaluated as a double-double (hi + lo) from exact
// products (fused multiply-add gives a product's rounding error exactly), and the determinants
// are summed as a double-double. A bound on the error comes with it, so that the rounding of
// sum / 6 to a double is taken only where the bound leaves one answer; anything else goes to the
// integers. The filter needs the FMA instruction, which the code is compiled for where the CPU
// has it.

constexpr double kUnitRoundoff = 0x1p-53;

// With every non-zero coordinate of magnitude in [2^-200, 2^200], no product or error term the
// filter forms under- or overflows, so each rounding is within kUnitRoundoff of its result.
constexpr double kFilterSmallest = 0x1p-200;
constexpr double kFilterLargest = 0x1p+200;

/// One group's sum: the value hi + lo; `magnitude` sums every product of three coordinates'
/// magnitudes |a_i b_j c_k|; `lo_moved` sums the magnitudes of every rounded addition into lo.
struct FilteredSum {
  double hi = 0.0;
  double lo = 0.0;
  double magnitude = 0.0;
  double lo_moved = 0.0;
};

/// s + e = a + b exactly (Knuth's two-sum).
[[gnu::always_inline]] inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double b_part = s - a;
  e = (a - (s - b_part)) + (b - b_part);
}

/// Adds one determinant dh + dl, whose terms' magnitudes sum to `magnitude`, to `sum`.
[[gnu::always_inline]] inline void add_determinant(FilteredSum& sum, double dh, double dl,
                                                   double magnitude) {
  double hi = 0.0, carried = 0.0;
  two_sum(sum.hi, dh, hi, carried);
  const double added = carried + dl;
  sum.hi = hi;
  sum.lo += added;
  sum.lo_moved += std::fabs(added) + std::fabs(sum.lo);
  sum.magnitude += magnitude;
}

/// Adds the part `from` into `to`.
void add_sum(FilteredSum& to, const FilteredSum& from) {
  add_determinant(to, from.hi, from.lo, from.magnitude);
  to.lo_moved += from.lo_moved;
}

/// a_k (b_i c_j - b_j c_i) as a high and a low part; adds the magnitudes of its two products of
/// three coordinates to `magnitude`.
[[gnu::target("fma"), gnu::always_inline]] inline void component_term(double ak, double bi,
                                                                      double cj, double bj,
                                                                      double ci, double& high,
                                                                      double& low,
                                                                      double& magnitude) {
  const double p1 = bi * cj;
  const double p2 = bj * ci;
  const double e1 = __builtin_fma(bi, cj, -p1);
  const double e2 = __builtin_fma(bj, ci, -p2);
  double d = 0.0, g = 0.0;
  two_sum(p1, -p2, d, g);
  const double component_low = g + (e1 - e2);
  high = ak * d;
  low = __builtin_fma(ak, d, -high) + ak * component_low;
  magnitude += std::fabs(ak) * (std::fabs(p1) + std::fabs(p2));
}

/// Error analysis, per facet, with u the unit roundoff and tau the sum of its six |a_i b_j c_k|:
/// a component of b x c is p1 - p2 + (e1 - e2) with p1 + e1 and p2 + e2 the exact products;
/// its low part is within 3 u^2 (|p1| + |p2|) of the truth. Multiplied by a's coordinate (exact
/// product again, the low part's product rounded) a component term is within 8.1 u^2 |a_k| (|p1|
/// + |p2|); adding the three terms as double-doubles rounds four more times, each within
/// 5.1 u^2 tau. So a determinant is within 29 u^2 tau, taken as 64 u^2 tau below. Summing rounds
/// each addition into lo within u of its result: u lo_moved in all.
[[gnu::target("fma")]] void add_filtered_determinants(const IndexedMesh& mesh,
                                                      const std::vector<std::uint32_t>& group,
                                                      std::size_t begin, std::size_t end,
                                                      FilteredSum* sums) {
  const Vec3* v = mesh.vertices.data();
  for (std::size_t f = begin; f < end; ++f) {
    if (group[f] == kNoGroup) continue;
    const auto& t = mesh.triangles[f];
    const Vec3& a = v[t[0]];
    const Vec3& b = v[t[1]];
    const Vec3& c = v[t[2]];
    double high[3], low[3], magnitude = 0.0;
    component_term(a.x, b.y, c.z, b.z, c.y, high[0], low[0], magnitude);
    component_term(a.y, b.z, c.x, b.x, c.z, high[1], low[1], magnitude);
    component_term(a.z, b.x, c.y, b.y, c.x, high[2], low[2], magnitude);
    double s1 = 0.0, r1 = 0.0, dh = 0.0, r2 = 0.0;
    two_sum(high[0], high[1], s1, r1);
    two_sum(s1, high[2], dh, r2);
    const double dl = ((low[0] + low[1]) + low[2]) + (r1 + r2);
    add_determinant(sums[group[f]], dh, dl, magnitude);
  }
}

/// The error bound of a sum: the per-facet bound and the additions' (see above), doubled for the
/// rounding of the bound's own sums.
double error_bound(const FilteredSum& sum) {
  return 2.0 *
         (64.0 * kUnitRoundoff * kUnitRoundoff * sum.magnitude + kUnitRoundoff * sum.lo_moved);
}

/// The double nearest to (hi + lo) / 6 when every value within `error` of hi + lo rounds to it.
[[gnu::target("fma")]] std::optional<double> decided_sixth(double hi, double lo, double error) {
  // No error: every product of coordinates was zero (or there was none), and so is the sum.
  if (error == 0.0) return 0.0;
  double h = 0.0, l = 0.0;
  two_sum(hi, lo, h, l);
  // Far from underflow, so that the remainder below is exact and the gaps normal. (The sums are
  // far from overflow: the coordinates are below 2^200.)
  if (!(std::fabs(h) >= 0x1p-900)) return std::nullopt;
  const double yh = h / 6.0;
  const double remainder = __builtin_fma(-6.0, yh, h);  // exact for a correctly rounded quotient
  const double yl = (remainder + l) / 6.0;              // two roundings, within 2 u |yl| or so
  double candidate = 0.0, residual = 0.0;
  two_sum(yh, yl, candidate, residual);
  const double distance =
      std::fabs(residual) + error / 6.0 * 1.01 + 4.0 * kUnitRoundoff * std::fabs(yl);
  const double gap = std::min(std::nextafter(candidate, HUGE_VAL) - candidate,
                              candidate - std::nextafter(candidate, -HUGE_VAL));
  if (!(distance < 0.4999 * gap)) return std::nullopt;
  return candidate;
}

/// The volumes by the filter, or nothing where it cannot be sure of one rounding.
std::optional<ExactVolumes> filtered_signed_volumes(
    const IndexedMesh& mesh, const std::vector<std::uint32_t>& group_of_facet,
    std::size_t num_groups, std::size_t parts) {
  if (!__builtin_cpu_supports("fma")) return std::nullopt;
  const bool in_range = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.vertices.size(), 4096), true,
      [&](const auto& range, bool ok) {
        for (std::size_t v = range.begin(); v < range.end() && ok; ++v) {
          const Vec3& p = mesh.vertices[v];
          for (const double x : {p.x, p.y, p.z}) {
            const double m = std::fabs(x);
            ok = ok && (m == 0.0 || (m >= kFilterSmallest && m <= kFilterLargest));
          }
        }
        return ok;
      },
      [](bool a, bool b) { return a && b; });
  if (!in_range) return std::nullopt;
  const std::size_t nf = mesh.triangles.size();
  std::vector<std::vector<FilteredSum>> part_sums(parts, std::vector<FilteredSum>(num_groups));
  tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
    add_filtered_determinants(mesh, group_of_facet, nf * part / parts, nf * (part + 1) / parts,
                              part_sums[part].data());
  });
  ExactVolumes result;
  result.by_group_mm3.resize(num_groups);
  FilteredSum total;
  for (std::size_t g = 0; g < num_groups; ++g) {
    FilteredSum sum;
    for (std::size_t part = 0; part < parts; ++part) add_sum(sum, part_sums[part][g]);
    const std::optional<double> volume = decided_sixth(sum.hi, sum.lo, error_bound(sum));
    if (!volume) return std::nullopt;
    result.by_group_mm3[g] = *volume;
    add_sum(total, sum);
  }
  const std::optional<double> volume = decided_sixth(total.hi, total.lo, error_bound(total));
  if (!volume) return std::nullopt;
  result.total_mm3 = *volume;
  result.decided_in_floating_point = true;
  return result;
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

namespace {

/// The facets are cut into parts summed on their own. A part holds a sum for every group, so
/// many groups (a soup of loose facets) make one part.
std::size_t parts_to_sum(std::size_t num_facets, std::size_t num_groups) {
  constexpr std::size_t kMaxParts = 8;
  constexpr std::size_t kMinFacetsAPart = 16384;
  return num_groups > 64 ? 1 : std::clamp<std::size_t>(num_facets / kMinFacetsAPart, 1, kMaxParts);
}

}  // namespace

ExactVolumes exact_signed_volumes(const IndexedMesh& mesh,
                                  const std::vector<std::uint32_t>& group_of_facet,
                                  std::size_t num_groups) {
  STRATA_ASSERT(group_of_facet.size() == mesh.triangles.size(), "one group per facet");
  if (std::optional<ExactVolumes> filtered = filtered_signed_volumes(
          mesh, group_of_facet, num_groups, parts_to_sum(mesh.triangles.size(), num_groups))) {
    return *std::move(filtered);
  }
  return integer_signed_volumes(mesh, group_of_facet, num_groups);
}

ExactVolumes integer_signed_volumes(const IndexedMesh& mesh,
                                    const std::vector<std::uint32_t>& group_of_facet,
                                    std::size_t num_groups) {
  STRATA_ASSERT(group_of_facet.size() == mesh.triangles.size(), "one group per facet");
  const std::size_t parts = parts_to_sum(mesh.triangles.size(), num_groups);
  // All coordinates become integers times one common power of two, so the determinants are
  // integer products and the sums need no gcd: exact, and their order does not matter. The
  // power is the lowest bit of any non-zero coordinate; the highest bit sets how wide the
  // integers are.
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
