// The Results panel: the regime, the solution's numbers with their symbols, and the fold
// amplitudes a_i. It keeps no state: every frame reads the scene's (cached) solution.
#pragma once

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

class ResultsPanel {
 public:
  void draw(Document& document, Renderer& renderer);
};

}  // namespace foldlab::gui
