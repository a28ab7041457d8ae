#include "app/gui/panels/intro_window.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"

namespace foldlab::gui {
namespace {

// The facts are those of docs/model.md, said for a class rather than for a reader of the paper.
constexpr const char* kParagraphs[] = {
    "A cloth hangs from two supports on its upper edge and carries its own weight. Move the "
    "supports towards each other by d and the upper edge, still of length L, has more cloth than "
    "span: it sags, and the cloth below it has nowhere to go but out of its plane.",
    "A thin fabric cannot carry compression: it buckles at once. Tension field theory takes that "
    "as its starting point. Wherever the cloth would be squeezed, it wrinkles instead, and the "
    "compressive stress is released; what is left carrying the load are tension rays, lines along "
    "which the cloth is pulled, running from support to support. The folds lie along those lines.",
    "So the wrinkled region folds into n wrinkles. Each fold line is a cosine arch hanging between "
    "the supports, and going up each arch is shallower than the one below it by the same ratio Q, "
    "so the folds crowd together towards the upper edge. Neighbouring folds stand out of the "
    "plane to either side, each by up to z_max at its middle. The model predicts how many folds "
    "there are (n), that ratio, and how far they stand out of the plane (z_max) from six "
    "numbers: the thickness t, the stiffness "
    "E and the weight w of the fabric, its height h and width L, and the support displacement d. "
    "A thicker, stiffer fabric makes fewer, larger folds; a heavier or taller one makes more.",
    "Two conditions close the model: the upper edge and the vertical fibre down the middle keep "
    "their lengths. A critical stress (eq. 7) says where the weight of the cloth below a fold is "
    "enough to buckle it, which fixes Q.",
};

// A walk through View > Tension field with a class, each step on the view (docs/explorer.md
// says the same for a reader).
constexpr const char* kFieldSteps[] = {
    "1. Rays carry the weight. The dark lines are tension rays: along each the cloth is pulled, "
    "across it it is not. The cloth between two rays hangs on them like a chain, and they take "
    "its weight to the supports. The arrows are the forces the supports put into the cloth: their "
    "\"up\" parts add up to the weight, their \"across\" parts are the thrust H that keeps the "
    "span from closing.",
    "2. No stress across a ray, so the cloth wrinkles across it. Orange (wrinkled: tension along "
    "the rays only) has more width than the rays leave it room for, and since it cannot take "
    "compression it folds out of its plane: the folds of the 3D view. Blue (taut) is pulled both "
    "ways; grey (slack) is pulled by nothing.",
    "3. Rays meet at point supports. A point can take a force from any direction, and every ray "
    "must end on something that holds it, so the rays fan into the supports and the tension grows "
    "without bound towards them: colour by tension shows it.",
    "4. The closed form beside the field. Tick \"closed form's cosines\": the magenta lines are "
    "the folds the model draws. Where they lie on the rays its assumption holds; where they part, "
    "it does not. The line over the picture gives the field's thrust beside the cosines' own.",
    "5. Move the supports. Drag d or any input: the field follows, on a coarser mesh while the "
    "hand moves. A field not yet solved for the inputs shown is drawn faded and said to be of the "
    "inputs before; a field that does not converge is never drawn as if it had.",
};

}  // namespace

void IntroWindow::draw(PanelContext& context) {
  if (!open_) {
    return;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const ImVec2 size(std::min(ems(40.0f), 0.9f * display.x),
                    std::min(ems(34.0f), 0.85f * display.y));
  ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (focus_) {
    ImGui::SetNextWindowFocus();
    focus_ = false;
  }
  const bool shown = ImGui::Begin(window_label().c_str(), &open_, ImGuiWindowFlags_NoCollapse);
  if (shown) {
    ++frames_shown_;
    context.renderer.fill_window_background();  // the style's window background is transparent
    // The text scrolls; "Close" stays in view under it.
    ImGui::BeginChild("##intro text", ImVec2(0.0f, -ImGui::GetFrameHeightWithSpacing()));
    ImGui::PushTextWrapPos(0.0f);
    for (const char* paragraph : kParagraphs) {
      ImGui::TextUnformatted(paragraph);
      ImGui::Spacing();
    }
    section("What each panel shows");
    for (const std::unique_ptr<Panel>& panel : context.panels) {
      if (const char* what = panel->introduction()) {
        ImGui::TextColored(kSectionText, "%s", panel->name());
        ImGui::SameLine();
        ImGui::TextUnformatted(what);
      }
    }
    ImGui::Spacing();
    section("The tension field, step by step (View > Tension field)");
    for (const char* step : kFieldSteps) {
      ImGui::TextUnformatted(step);
      ImGui::Spacing();
    }
    ImGui::TextUnformatted(
        "docs/model.md in the FoldLab folder states the model with its equations and units.");
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
    if (ImGui::Button("Close")) {
      open_ = false;
    }
    const int escape = ImGui::GetKeyIndex(ImGuiKey_Escape);
    if (escape >= 0 && ImGui::IsKeyPressed(escape, false) &&
        ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows)) {
      open_ = false;
    }
  }
  ImGui::End();
}

void IntroWindow::report(nlohmann::json& state, PanelContext& /*context*/) const {
  state["intro_open"] = open_;
}

}  // namespace foldlab::gui
