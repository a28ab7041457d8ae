// The Parameters panel: one slider per input of the cloth, its hanging and eq. 7's K, each with
// the range, scale, format, unit and help of its row in the input table; the model's choices;
// the 3D grid's resolution. Edits go into the document and are committed as they happen.
#pragma once

#include <functional>
#include <map>
#include <string>

#include <imgui.h>

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// Where a parameter slider was drawn in the last frame, for input playback: its frame and where
// its handle sits (0 at the left end, 1 at the right).
struct SliderPlace {
  ImVec2 min;
  ImVec2 max;
  double fraction = 0.0;
};

class ParametersPanel {
 public:
  void draw(Document& document, Renderer& renderer);
  // By input key; a slider hidden last frame keeps its older place.
  const std::map<std::string, SliderPlace, std::less<>>& slider_places() const { return places_; }

 private:
  std::map<std::string, SliderPlace, std::less<>> places_;
};

}  // namespace foldlab::gui
