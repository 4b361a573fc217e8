#include "strata/repair/repair_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <new>
#include <utility>
#include <vector>

#include "repair/repair_internal.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::repair {

const char* facet_change_name(FacetChangeKind kind) {
  switch (kind) {
    case FacetChangeKind::RemovedDegenerate:
      return "removed-degenerate";
    case FacetChangeKind::RemovedDuplicate:
      return "removed-duplicate";
    case FacetChangeKind::RemovedCancellingDuplicate:
      return "removed-cancelling-duplicate";
    case FacetChangeKind::SplitAtTJunction:
      return "split-at-t-junction";
    case FacetChangeKind::Flipped:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "flipped";
}

namespace {

bool finite(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

RepairResult run_repair(const TriangleSoup& soup, const RepairOptions& options) {
  RepairResult result;
  RepairLog& log = result.log;
  detail::CleanSoup clean = detail::clean_soup(soup, options, log);
  const std::vector<detail::OutputFacet> facets = detail::orient_and_close(clean, options, log);

  TriangleSoup& out = result.soup;
  out.format = "repaired";
  out.diagnostics = soup.diagnostics;
  out.triangles.reserve(facets.size());
  std::vector<bool> kept(soup.triangles.size(), false);
  std::vector<bool> flipped(soup.triangles.size(), false);
  for (const detail::OutputFacet& f : facets) {
    if (f.clean_index < 0) {
      out.triangles.push_back(f.corners);
      continue;
    }
    const detail::WorkFacet& w = clean.facets[static_cast<std::size_t>(f.clean_index)];
    const FacetIndex origin = w.origin;
    if (w.piece) {
      out.triangles.push_back(f.corners);
    } else {
      // The input's own corners, bit for bit (the weld treats -0 and +0 as one point).
      const auto& t = soup.triangles[origin];
      out.triangles.push_back(f.flipped ? std::array<Vec3, 3>{t[0], t[2], t[1]} : t);
    }
    kept[origin] = true;
    if (f.flipped) flipped[origin] = true;
  }

  std::vector<FacetChange>& changes = clean.changes;
  for (std::size_t i = 0; i < flipped.size(); ++i) {
    if (flipped[i]) changes.push_back({static_cast<FacetIndex>(i), FacetChangeKind::Flipped});
  }
  // By facet, then in the order the steps ran (the kinds are declared in that order).
  std::stable_sort(changes.begin(), changes.end(), [](const FacetChange& a, const FacetChange& b) {
    if (a.facet != b.facet) return a.facet < b.facet;
    return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  });
  log.changes = std::move(changes);
  log.kept_input_facets = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), true));
  log.facets_flipped = static_cast<std::size_t>(std::count(flipped.begin(), flipped.end(), true));
  log.output_facets = out.triangles.size();
  log.output_vertices = weld_vertices(out).vertices.size();

  STRATA_ASSERT(log.input_facets == log.kept_input_facets + log.degenerate_facets_removed +
                                        log.duplicate_facets_removed +
                                        log.cancelling_duplicates_removed,
                "every input facet is kept or removed once");
  STRATA_ASSERT(log.output_facets ==
                    log.kept_input_facets + log.t_junction_facets_added + log.hole_facets_added,
                "every output facet is a kept facet, a piece or a patch");
  return result;
}

}  // namespace

Result<RepairResult> repair_mesh(const TriangleSoup& soup, const RepairOptions& options) {
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    for (const Vec3& p : soup.triangles[f]) {
      if (!finite(p)) {
        return Error{ErrorCode::BadInput, "a corner has a coordinate that is not finite",
                     fmt::format("facet {}", f)};
      }
    }
  }
  try {
    return run_repair(soup, options);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception& e) {
    // CGAL reports failed preconditions by throwing (CGAL::Failure_exception).
    return Error{ErrorCode::Internal, fmt::format("mesh repair failed in CGAL: {}", e.what()), {}};
  }
}

}  // namespace strata::repair
