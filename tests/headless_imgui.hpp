// An ImGui context with no platform and no GPU, for tests and benchmarks that build frames and
// read their draw data: a display size, 60 frames a second, no ini file, and the font atlas built
// as the null renderer builds it.
#pragma once

#include <imgui.h>

#include "app/gui/renderer.hpp"

namespace foldlab::testing {

inline ImGuiContext* create_headless_imgui(ImVec2 display) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = display;
  io.DeltaTime = 1.0f / 60.0f;
  gui::NullRenderer().fonts_changed();
  return context;
}

}  // namespace foldlab::testing
