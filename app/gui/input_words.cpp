#include "app/gui/input_words.hpp"

#include <imgui.h>

namespace foldlab::gui {

const char* hint_words(Hint hint, bool coarse_pointer) {
  switch (hint) {
    case Hint::type_value:
      return coarse_pointer ? "long press a slider to type" : "Ctrl+click a slider to type";
    case Hint::parameters_intro:
      return coarse_pointer
                 ? "the six numbers above as sliders (a long press types one; drag with the "
                   "finger above or below a slider for finer steps); a red slider is a value "
                   "the model refuses, with the reason below."
                 : "the six numbers above as sliders (Ctrl+click to type one); a red slider is "
                   "a value the model refuses, with the reason below.";
    case Hint::cloth_view:
      return coarse_pointer ? "one finger: orbit, two fingers: pan, pinch: zoom"
                            : "drag: orbit, right-drag: pan, wheel: zoom";
    case Hint::fold_plot:
      return coarse_pointer ? "pinch: zoom, drag: pan, double tap: autoscale"
                            : "wheel: zoom, drag: pan, double-click: autoscale";
    case Hint::interval_details:
      return coarse_pointer ? "tap them for how often they held" : "hover for how often they held";
    case Hint::present_view:
      return coarse_pointer ? "Fill the screen with this view (or double tap its title); "
                              "tap here again to return"
                            : "Fill the window with this view (or double-click its title); "
                              "Esc returns";
  }
  return "";
}

const char* hint_words(Hint hint) {
  return hint_words(hint, (ImGui::GetIO().ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0);
}

}  // namespace foldlab::gui
