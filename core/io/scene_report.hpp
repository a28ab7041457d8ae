// The scene's per-stage counters as JSON and as text (for --stats and the GUI overlay).
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/geometry/scene.hpp"

namespace foldlab {

// {"solution": {"evaluations": 1, "total_ms": 0.01, "last_ms": 0.01}, "fold_lines": {...}, ...}
nlohmann::json scene_stats_to_json(const Scene& scene);
std::string scene_stats_table(const Scene& scene);

}  // namespace foldlab
