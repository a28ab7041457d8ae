// The hints that tell how to work a control, in the words of the pointer in hand: a mouse's
// (Ctrl+click, right-drag, wheel, hover) or a finger's (long press, two fingers, pinch, tap) on a
// coarse pointer, a touch screen, where the mouse's words say nothing. Every such hint goes through
// hint_words, so that the two sets stay side by side.
#pragma once

namespace foldlab::gui {

enum class Hint {
  type_value,        // under the sliders: how to type a value
  parameters_intro,  // the introduction's line on the Parameters panel
  cloth_view,        // over the 3D view: orbit, pan, zoom
  fold_plot,         // beside the fold plot's settings: zoom, pan, autoscale
  interval_details,  // under the results' prediction intervals: how to see how often they held
  present_view,      // the tooltip of a tile's present button
};

// The words for a fine pointer (a mouse) or a coarse one (a finger).
const char* hint_words(Hint hint, bool coarse_pointer);
// The words for the pointer the explorer is used with now: coarse while ImGui's io has
// ImGuiConfigFlags_IsTouchScreen, which the appearance sets from the screen (Appearance).
const char* hint_words(Hint hint);

}  // namespace foldlab::gui
