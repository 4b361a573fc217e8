// A reference reader: every corpus file that Debian's assimp (`assimp info`, package
// assimp-utils) reads, strata reads too, with assimp's count of faces after its triangulation,
// unless the file is listed below with the reason of the difference.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "strata/io/read_mesh.hpp"
#include "support/corpus.hpp"

namespace strata::io {
namespace {

using test::CorpusEntry;

/// A corpus file on which strata and assimp differ, and why; strata_faces is empty for a file
/// strata refuses.
struct KnownDifference {
  std::string_view path;
  std::uint64_t assimp_faces;
  std::optional<std::uint64_t> strata_faces;
  std::string_view reason;
};

constexpr KnownDifference kKnownDifferences[] = {
    {"assimp-testmodels/models/OBJ/number_formats.obj", 1, std::nullopt,
     "line 11 has the coordinate '3.1+e2', which the number grammar of every text format refuses "
     "(README, Numbers in text formats); assimp accepts it"},
    {"assimp-testmodels/models/OFF/invalid.off", 3, std::nullopt,
     "the header declares 4 faces and the file ends inside its face list, which holds a face of "
     "0 corners and a stray carriage return: bad input with the line named (SPEC §4); assimp "
     "recovers 3 faces"},
    {"openscad/tests/data/amf/amf_broken.amf", 12, std::nullopt,
     "AMF is not a format strata reads"},
    {"assimp-testmodels/models/OBJ/spider.obj", 1340, 1368,
     "assimp's raw import has the file's 1368 faces, its default post-processing leaves 1340 "
     "(triangles and lines); strata keeps every facet (the manifest counts 1368)"},
    {"cgal-data/data/meshes/blobby-shuffled.off", 4048, 4050,
     "the file holds the 4050 triangles its header declares (the manifest counts 4050); assimp's "
     "OFF reader returns 2 fewer"},
    {"cgal-data/data/meshes/oblong-shuffled.off", 838, 840,
     "the file holds the 840 triangles its header declares (the manifest counts 840); assimp's OFF "
     "reader returns 2 fewer"},
    {"cgal-data/data/meshes/mpi.off", 148, 180,
     "52 polygons of 3 to 10 corners fan into 180 triangles (the manifest counts 180); assimp's "
     "OFF reader keeps 48 of the 52 faces, leaving out the 4 of 10 corners"},
    {"common-3d-test-models/data/igea.ply", 1, 268686,
     "the faces are a PLY tristrips element, which assimp does not read; strata reads the strips"},
    {"numpy-stl/tests/stl_ascii/HalfDonut.stl", 287, 288,
     "288 facets in mixed-case keywords (the manifest counts 288); assimp's ASCII STL reader "
     "returns 287"},
    {"openscad/tests/data/stl/toomanyvertices.stl", 13, 14,
     "one facet has 4 vertices: strata fans it into 2 triangles with a warning, assimp keeps one"},
    {"stl-models/broken/fourVertices.ascii.stl", 4, 5,
     "one facet has 4 vertices: strata fans it into 2 triangles with a warning, assimp keeps one"},
};

const KnownDifference* known_difference(std::string_view path) {
  for (const KnownDifference& d : kKnownDifferences) {
    if (d.path == path) return &d;
  }
  return nullptr;
}

/// `text` quoted for the shell.
std::string shell_quoted(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

/// What `assimp info` made of a file.
struct AssimpInfo {
  bool ran = false;                    ///< the assimp command exists and ran
  std::optional<std::uint64_t> faces;  ///< "Faces:" of its summary; empty when it refused the file
};

AssimpInfo assimp_info(const std::filesystem::path& path) {
  AssimpInfo info;
  const std::string command = "assimp info " + shell_quoted(path.string()) + " -s 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return info;
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    output.append(buffer, n);
  const int status = ::pclose(pipe);
  // The shell's 127: no assimp on the PATH.
  info.ran = !(WIFEXITED(status) && WEXITSTATUS(status) == 127);
  const std::size_t at = output.find("\nFaces:");
  if (at != std::string::npos) {
    info.faces = std::stoull(output.substr(at + 7));
  }
  return info;
}

class AssimpAgreement : public testing::TestWithParam<CorpusEntry> {};

TEST_P(AssimpAgreement, WhatAssimpReadsStrataReadsWithTheSameFaces) {
  const CorpusEntry& entry = GetParam();
  const std::string path = entry.path.generic_string();
  const AssimpInfo assimp = assimp_info(entry.full_path());
  ASSERT_TRUE(assimp.ran) << "no `assimp` command: install Debian's assimp-utils (bash "
                             "scripts/setup.sh test)";
  const KnownDifference* known = known_difference(path);
  if (!assimp.faces) {
    EXPECT_EQ(known, nullptr) << path << ": assimp no longer reads it; remove its entry";
    return;
  }
  const auto soup = read_mesh(entry.full_path());
  if (known != nullptr) {
    EXPECT_EQ(*assimp.faces, known->assimp_faces) << path << ": " << known->reason;
    if (!known->strata_faces) {
      EXPECT_FALSE(soup) << path << " is read now (" << soup->triangles.size()
                         << " facets): remove its entry (" << known->reason << ")";
    } else {
      ASSERT_TRUE(soup) << soup.error().to_string();
      EXPECT_EQ(soup->triangles.size(), *known->strata_faces) << path << ": " << known->reason;
    }
    return;
  }
  ASSERT_TRUE(soup) << "assimp reads " << *assimp.faces
                    << " faces; strata refuses: " << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), *assimp.faces) << path;
}

INSTANTIATE_TEST_SUITE_P(Corpus, AssimpAgreement, testing::ValuesIn(test::load_corpus_manifest()),
                         test::CorpusTestName{});

}  // namespace
}  // namespace strata::io
