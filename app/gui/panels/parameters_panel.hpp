// The Parameters panel: one slider per input of the cloth, its hanging and eq. 7's K, each with
// the range, scale, format, unit and help of its row in the input table; the model's choices;
// the 3D grid's resolution. Edits go into the document and are committed as they happen.
#pragma once

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

class ParametersPanel {
 public:
  void draw(Document& document, Renderer& renderer);
};

}  // namespace foldlab::gui
