#include "support/mesh_reading.hpp"

#include <gtest/gtest.h>

#include <string>

#include "strata/io/read_mesh.hpp"

namespace strata::test {

std::filesystem::path adversarial(std::string_view name) {
  return std::filesystem::path(STRATA_DATA_DIR) / "adversarial" / name;
}

std::filesystem::path corpus_file(std::string_view relative) {
  return std::filesystem::path(STRATA_SHARED_DIR) / "corpus" / relative;
}

const Diagnostic* find_diagnostic(const TriangleSoup& soup, std::string_view code) {
  for (const Diagnostic& d : soup.diagnostics) {
    if (d.code == code) return &d;
  }
  return nullptr;
}

bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

void expect_read_with_diagnostic(const std::filesystem::path& path, std::size_t facets,
                                 std::string_view code) {
  const auto soup = io::read_mesh(path);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), facets) << path;
  EXPECT_NE(find_diagnostic(*soup, code), nullptr) << path << ": no " << code;
}

void expect_refused(const std::filesystem::path& path, std::string_view part,
                    std::optional<std::string_view> place) {
  const auto soup = io::read_mesh(path);
  ASSERT_FALSE(soup) << path << " was read";
  if (place) {
    EXPECT_EQ(soup.error().location, path.string() + std::string(*place));
  }
  EXPECT_TRUE(contains(soup.error().message, part)) << soup.error().message;
}

}  // namespace strata::test
