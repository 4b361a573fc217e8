#include "support/read_file.hpp"

#include <fstream>
#include <sstream>

namespace strata::test {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace strata::test
