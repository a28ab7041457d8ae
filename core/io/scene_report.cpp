#include "core/io/scene_report.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

namespace foldlab {
namespace {

constexpr Stage kStages[] = {Stage::solution, Stage::fold_lines, Stage::grid, Stage::normals};

}  // namespace

nlohmann::json scene_stats_to_json(const Scene& scene) {
  nlohmann::json out = nlohmann::json::object();
  for (Stage stage : kStages) {
    const StageStats& s = scene.stats(stage);
    out[std::string(to_string(stage))] = {
        {"evaluations", s.evaluations}, {"total_ms", s.total_ms}, {"last_ms", s.last_ms}};
  }
  return out;
}

std::string scene_stats_table(const Scene& scene) {
  std::string out = "Pipeline stages (evaluations, time)\n";
  for (Stage stage : kStages) {
    const StageStats& s = scene.stats(stage);
    char line[128];
    std::snprintf(line, sizeof line, "  %-12s %6llu x  %10.3f ms total  %10.3f ms last\n",
                  std::string(to_string(stage)).c_str(),
                  static_cast<unsigned long long>(s.evaluations), s.total_ms, s.last_ms);
    out += line;
  }
  return out;
}

}  // namespace foldlab
