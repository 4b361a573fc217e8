// Mesh diagnostics against the shared corpus: for every STL file under 5 MB, the counts of
// diagnose_mesh() must equal those of MANIFEST.tsv's defects_summary column, or the difference
// must be listed below with its reason.

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/diagnose/mesh_report.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "support/corpus.hpp"

namespace strata::diagnose {
namespace {

using test::CorpusEntry;

constexpr std::uint64_t kMaxBytes = 5'000'000;

/// The quantities compared, as named in failure messages and in kAllowedDifferences.
constexpr std::string_view kQuantities[] = {
    "boundary edges",          "boundary loops",
    "non-manifold edges",      "degenerate facets",
    "duplicate facets",        "inconsistent edges",
    "flipped normals",         "zero normals",
    "self-intersecting pairs", "parts",
};

/// A count on which strata and the manifest disagree for a known reason.
struct AllowedDifference {
  std::string_view path;
  std::string_view quantity;
  std::uint64_t manifest;
  std::uint64_t strata;
  std::string_view reason;
};

constexpr AllowedDifference kAllowedDifferences[] = {
    {"numpy-stl/tests/stl_tests/bwb.stl", "flipped normals", 154, 155,
     "facet 4355's stored normal is perpendicular to its facet within 3e-11 (dot -1.3e-16 against "
     "terms of 1e-5); the exact sign is negative, the manifest's rounded evaluation is not"},
    {"openscad/tests/data/scad/bugs/issue945e.stl", "zero normals", 0, 1,
     "one facet stores 'normal nan nan nan'; strata's reader replaces a non-finite normal by "
     "(0, 0, 0) with a warning, the manifest does not count it as zero"},
    {"stl-models/misc/multiWordName.bin.stl", "flipped normals", 1, 2,
     "facet 1 has coordinates of 1e29: in double the two 6e57 terms of its cross product cancel "
     "and the dot product comes out +8e-14, exactly it is -1.4e29"},
};

/// Files strata refuses to read although the manifest has counts for them (or none at all).
struct ExpectedRejection {
  std::string_view path;
  std::string_view reason;
};

constexpr ExpectedRejection kExpectedRejections[] = {
    {"stl-models/broken/incorrectFaceCounter.bin.stl",
     "the header declares 66 facets and the file holds 4: a truncated binary STL is bad input "
     "(SPEC §4), the manifest reads the 4 facets"},
    {"openscad/tests/data/stl/invalidvertex.stl",
     "line 89 has the coordinate 'blah': bad input with the line named, the manifest's parser "
     "drops the facet"},
    {"openscad/tests/data/stl/unparseable.stl",
     "line 4 holds a control byte inside a vertex: bad input with the line named, the manifest's "
     "parser recovers a facet"},
    {"trimesh/models/ascii.stl.zip", "zip archives are not a supported container (gzip is)"},
};

/// The counts of one defects_summary cell; a quantity the manifest does not list is 0 (1 for
/// parts).
struct ManifestCounts {
  std::map<std::string, std::uint64_t, std::less<>> counts;
  bool zero_facets = false;
};

std::uint64_t leading_count(std::string_view text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{}) ADD_FAILURE() << "no count in manifest item '" << text << "'";
  return value;
}

ManifestCounts parse_defects(const std::vector<std::string>& defects) {
  ManifestCounts m;
  for (std::string_view q : kQuantities) m.counts[std::string(q)] = 0;
  m.counts["parts"] = 1;
  const std::pair<std::string_view, std::string_view> simple[] = {
      {"non-manifold edges: ", "non-manifold edges"},
      {"degenerate facets: ", "degenerate facets"},
      {"duplicate facets: ", "duplicate facets"},
      {"inconsistently oriented edges: ", "inconsistent edges"},
      {"stored normals opposite winding: ", "flipped normals"},
      {"zero stored normals: ", "zero normals"},
      {"self-intersecting tri pairs: ", "self-intersecting pairs"},
      {"parts: ", "parts"},
  };
  for (std::string_view item : defects) {
    if (item == "ZERO FACETS") m.zero_facets = true;
    if (item.starts_with("open: ")) {
      // "open: 52 boundary edges/2 loops"
      item.remove_prefix(6);
      m.counts["boundary edges"] = leading_count(item);
      m.counts["boundary loops"] = leading_count(item.substr(item.find('/') + 1));
    }
    for (const auto& [prefix, quantity] : simple) {
      if (item.starts_with(prefix))
        m.counts[std::string(quantity)] = leading_count(item.substr(prefix.size()));
    }
  }
  return m;
}

std::map<std::string, std::uint64_t, std::less<>> strata_counts(const MeshReport& r) {
  return {
      {"boundary edges", r.boundary_edges.count},
      {"boundary loops", r.num_boundary_loops},
      {"non-manifold edges", r.non_manifold_edges.count},
      {"degenerate facets", r.degenerate_facets.count},
      {"duplicate facets", r.duplicate_facets.count},
      {"inconsistent edges", r.inconsistent_edges.count},
      {"flipped normals", r.flipped_normals.count},
      {"zero normals", r.zero_normals.count},
      {"self-intersecting pairs", r.self_intersections.count},
      {"parts", r.shells.size()},
  };
}

const AllowedDifference* allowed_difference(std::string_view path, std::string_view quantity) {
  for (const auto& d : kAllowedDifferences) {
    if (d.path == path && d.quantity == quantity) return &d;
  }
  return nullptr;
}

const ExpectedRejection* expected_rejection(std::string_view path) {
  for (const auto& r : kExpectedRejections) {
    if (r.path == path) return &r;
  }
  return nullptr;
}

std::vector<CorpusEntry> stl_entries() {
  std::vector<CorpusEntry> out;
  for (CorpusEntry& e : test::load_corpus_manifest()) {
    // STL in any container (plain, gzip, zip), up to kMaxBytes as stored.
    if (e.format.starts_with("stl") && e.bytes < kMaxBytes) out.push_back(std::move(e));
  }
  return out;
}

class CheckCorpus : public testing::TestWithParam<CorpusEntry> {};

TEST_P(CheckCorpus, CountsMatchManifest) {
  const CorpusEntry& entry = GetParam();
  const std::string path = entry.path.generic_string();
  const ManifestCounts manifest = parse_defects(entry.defects);

  const auto soup = io::read_mesh(entry.full_path());
  if (!soup) {
    if (manifest.zero_facets) return;  // rejected as it should be: no facets
    const ExpectedRejection* rejection = expected_rejection(path);
    EXPECT_NE(rejection, nullptr) << "unexpected read error: " << soup.error().to_string();
    return;
  }
  EXPECT_FALSE(manifest.zero_facets)
      << "the manifest has no facets, strata read " << soup->triangles.size();
  EXPECT_EQ(expected_rejection(path), nullptr) << "listed as rejected, but strata reads it";

  const MeshReport report = diagnose_mesh(weld_vertices(*soup), *soup);
  EXPECT_FALSE(report.self_intersections_truncated);
  const auto ours = strata_counts(report);
  for (std::string_view quantity : kQuantities) {
    const std::uint64_t expected = manifest.counts.find(quantity)->second;
    const std::uint64_t actual = ours.find(quantity)->second;
    const AllowedDifference* allowed = allowed_difference(path, quantity);
    if (allowed == nullptr) {
      EXPECT_EQ(actual, expected) << quantity << ": strata " << actual << ", manifest " << expected;
    } else {
      // The allowance must describe what happens, so it cannot go stale silently.
      EXPECT_EQ(expected, allowed->manifest)
          << quantity << ": manifest changed; " << allowed->reason;
      EXPECT_EQ(actual, allowed->strata) << quantity << ": strata changed; " << allowed->reason;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, CheckCorpus, testing::ValuesIn(stl_entries()),
                         test::CorpusTestName{});

TEST(CheckCorpusAllowances, NameKnownFilesAndQuantities) {
  const auto entries = stl_entries();
  const auto known = [&](std::string_view path) {
    return std::any_of(entries.begin(), entries.end(),
                       [&](const CorpusEntry& e) { return e.path.generic_string() == path; });
  };
  for (const auto& d : kAllowedDifferences) {
    EXPECT_TRUE(known(d.path)) << d.path;
    EXPECT_NE(std::find(std::begin(kQuantities), std::end(kQuantities), d.quantity),
              std::end(kQuantities))
        << d.quantity;
  }
  for (const auto& r : kExpectedRejections) EXPECT_TRUE(known(r.path)) << r.path;
}

}  // namespace
}  // namespace strata::diagnose
