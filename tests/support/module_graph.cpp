#include "module_graph.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

namespace strata::test {

namespace {

/// The modules nothing may include: the command line and the facade over the library.
const std::set<std::string, std::less<>> kTopModules = {"cli", "strata"};

std::string first_folder(std::string_view path) {
  const std::size_t slash = path.find('/');
  return slash == std::string_view::npos ? std::string() : std::string(path.substr(0, slash));
}

std::string module_of_target(std::string_view target, const std::set<std::string>& modules) {
  if (target == "strata/strata.hpp") return "strata";
  if (target.starts_with("strata/")) target.remove_prefix(7);
  std::string m = first_folder(target);
  return modules.count(m) != 0 ? m : std::string();
}

std::string where(const IncludeLine& inc) {
  return inc.file + ":" + std::to_string(inc.line) + " includes \"" + inc.target + "\"";
}

/// A module-level edge and the first include line that makes it.
using Edges = std::map<std::string, std::map<std::string, const IncludeLine*>>;

/// The strongly connected components of more than one module (Tarjan).
std::vector<std::vector<std::string>> cycles_of(const std::set<std::string>& modules,
                                                const Edges& edges) {
  std::map<std::string, int> index;
  std::map<std::string, int> low;
  std::vector<std::string> stack;
  std::set<std::string> on_stack;
  std::vector<std::vector<std::string>> out;
  int counter = 0;
  std::function<void(const std::string&)> visit = [&](const std::string& v) {
    index[v] = low[v] = counter++;
    stack.push_back(v);
    on_stack.insert(v);
    if (const auto it = edges.find(v); it != edges.end()) {
      for (const auto& [w, inc] : it->second) {
        if (index.count(w) == 0) {
          visit(w);
          low[v] = std::min(low[v], low[w]);
        } else if (on_stack.count(w) != 0) {
          low[v] = std::min(low[v], index[w]);
        }
      }
    }
    if (low[v] != index[v]) return;
    std::vector<std::string> component;
    std::string w;
    do {
      w = stack.back();
      stack.pop_back();
      on_stack.erase(w);
      component.push_back(w);
    } while (w != v);
    if (component.size() > 1) {
      std::sort(component.begin(), component.end());
      out.push_back(std::move(component));
    }
  };
  for (const std::string& m : modules) {
    if (index.count(m) == 0) visit(m);
  }
  return out;
}

/// One cycle through the component, from its first module back to it, as the include lines that
/// make its edges (breadth-first, so the cycle is a shortest one).
std::vector<const IncludeLine*> cycle_through(const std::vector<std::string>& component,
                                              const Edges& edges) {
  const std::set<std::string> inside(component.begin(), component.end());
  const std::string& start = component.front();
  std::map<std::string, std::pair<std::string, const IncludeLine*>> came_from;
  std::vector<std::string> queue = {start};
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const std::string v = queue[q];
    const auto it = edges.find(v);
    if (it == edges.end()) continue;
    for (const auto& [w, inc] : it->second) {
      if (inside.count(w) == 0 || came_from.count(w) != 0) continue;
      came_from[w] = {v, inc};
      if (w == start) break;
      queue.push_back(w);
    }
    if (came_from.count(start) != 0) break;
  }
  std::vector<const IncludeLine*> path;
  if (came_from.count(start) == 0) return path;
  std::string v = start;
  do {
    const auto& [from, inc] = came_from.at(v);
    path.push_back(inc);
    v = from;
  } while (v != start);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::string module_of_file(std::string_view file) {
  if (file == "include/strata/strata.hpp") return "strata";
  for (const std::string_view root : {"src/", "include/strata/"}) {
    if (file.starts_with(root)) return first_folder(file.substr(root.size()));
  }
  return {};
}

std::vector<std::string> check_module_graph(const std::vector<IncludeLine>& includes) {
  std::set<std::string> modules;
  for (const IncludeLine& inc : includes) {
    if (std::string m = module_of_file(inc.file); !m.empty()) modules.insert(std::move(m));
  }
  std::vector<std::string> problems;
  Edges edges;
  for (const IncludeLine& inc : includes) {
    const std::string from = module_of_file(inc.file);
    const std::string to = module_of_target(inc.target, modules);
    if (from.empty() || to.empty() || from == to) continue;
    edges[from].emplace(to, &inc);
    if (kTopModules.count(to) != 0) {
      problems.push_back(where(inc) + ": nothing may include module " + to);
    }
    if (inc.target.ends_with("_internal.hpp")) {
      problems.push_back(where(inc) + ": an internal header of module " + to + ", included from " +
                         from);
    }
  }
  for (const std::vector<std::string>& component : cycles_of(modules, edges)) {
    std::string message = "module cycle";
    const char* separator = ": ";
    for (const IncludeLine* inc : cycle_through(component, edges)) {
      message += separator + where(*inc) + " (" + module_of_file(inc->file) + " -> " +
                 module_of_target(inc->target, modules) + ")";
      separator = ", then ";
    }
    problems.push_back(std::move(message));
  }
  return problems;
}

std::vector<IncludeLine> read_includes(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  static const std::regex kInclude(R"re(^\s*#\s*include\s+"([^"]+)")re");
  std::vector<std::string> files;
  for (const char* dir : {"src", "include"}) {
    if (!fs::is_directory(root / dir)) continue;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root / dir)) {
      const fs::path& p = e.path();
      if (!e.is_regular_file()) continue;
      if (p.extension() != ".hpp" && p.extension() != ".h" && p.extension() != ".cpp") continue;
      files.push_back(fs::relative(p, root).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<IncludeLine> out;
  for (const std::string& file : files) {
    std::ifstream in(root / file);
    std::string text;
    std::size_t line = 0;
    while (std::getline(in, text)) {
      ++line;
      std::smatch m;
      if (std::regex_search(text, m, kInclude)) out.push_back({file, line, m[1].str()});
    }
  }
  return out;
}

}  // namespace strata::test
