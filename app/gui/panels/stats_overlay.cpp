#include "app/gui/panels/stats_overlay.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

namespace foldlab::gui {

void stats_overlay(bool& open, const Scene& scene, const RenderCounters& counters) {
  if (!open) {
    return;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y - 10.0f), ImGuiCond_Always,
                          ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin("pipeline", &open,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    ImGui::Text("stage        evals     last ms");
    for (Stage stage : {Stage::solution, Stage::fold_lines, Stage::grid, Stage::normals}) {
      const StageStats& st = scene.stats(stage);
      ImGui::Text("%-12s %5llu  %10.3f", std::string(to_string(stage)).c_str(),
                  static_cast<unsigned long long>(st.evaluations), st.last_ms);
    }
    ImGui::Text("mesh uploads %llu, fold-line uploads %llu",
                static_cast<unsigned long long>(counters.mesh_uploads),
                static_cast<unsigned long long>(counters.fold_line_uploads));
    ImGui::Text("%.1f ms/frame", 1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f));
  }
  ImGui::End();
}

}  // namespace foldlab::gui
