#pragma once
// A minimal binary STL reader shared by the peer harnesses: corners welded by exact equality of
// their float32 coordinates (as strata's weld_vertices does), so each peer library gets an
// indexed mesh without paying for a general-purpose reader.

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace strata::bench {

struct BinaryStl {
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

inline BinaryStl read_binary_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 84) throw std::runtime_error(path + ": too short for a binary STL");
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() != 84 + 50 * std::uint64_t{count}) {
    throw std::runtime_error(path + ": not a binary STL (" + std::to_string(count) +
                             " facets declared, " + std::to_string(bytes.size()) + " bytes)");
  }
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
      std::uint64_t h = k[0];
      h = h * 0x9E3779B97F4A7C15ull ^ k[1];
      h = h * 0x9E3779B97F4A7C15ull ^ k[2];
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  BinaryStl mesh;
  mesh.triangles.reserve(count);
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, KeyHash> index;
  index.reserve(count);
  for (std::uint32_t f = 0; f < count; ++f) {
    const char* corner = bytes.data() + 84 + 50 * std::size_t{f} + 12;
    std::array<std::uint32_t, 3> triangle{};
    for (int c = 0; c < 3; ++c, corner += 12) {
      std::array<float, 3> p{};
      std::memcpy(p.data(), corner, 12);
      // +0 and -0 are one point.
      for (float& x : p) x = x + 0.0f;
      std::array<std::uint32_t, 3> key{};
      std::memcpy(key.data(), p.data(), 12);
      const auto [it, added] = index.try_emplace(key, static_cast<std::uint32_t>(index.size()));
      if (added) mesh.vertices.push_back(p);
      triangle[c] = it->second;
    }
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

}  // namespace strata::bench
