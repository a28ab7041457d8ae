// n, Q and z_max of every preset that carries published results, with both methods, as
// `foldlab compare --json` prints them: compiled to WebAssembly, its output must equal the desktop
// program's (compare_rows.py). Usage: paper_rows PRESETS_DIR
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/analysis/comparison.hpp"
#include "core/io/preset.hpp"

int main(int argc, char** argv) {
  using namespace foldlab;
  if (argc != 2) {
    std::cerr << "usage: paper_rows PRESETS_DIR\n";
    return 2;
  }
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1])) {
    if (entry.path().extension() == ".json") {
      paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  nlohmann::json out = nlohmann::json::array();
  for (const std::filesystem::path& path : paths) {
    const Preset preset = load_preset(path);
    const PublishedResult& pub = preset.published;
    if (!pub.n && !pub.z_max_mm && !pub.Q) {
      continue;
    }
    nlohmann::json row = {{"name", preset.name}};
    for (const Method method : {Method::paper, Method::exact}) {
      Parameters p = preset.parameters;
      p.model.method = method;
      const PublishedComparison c = compare_with_published(pub, p);
      row[method == Method::paper ? "paper" : "exact"] = {{"n", c.solution.n},
                                                          {"n_capped", c.solution.n_capped},
                                                          {"z_max_mm", c.solution.z_max_mm},
                                                          {"Q", c.solution.Q}};
    }
    out.push_back(row);
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}
