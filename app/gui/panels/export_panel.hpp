// The Export menu (in the menu bar, so that it is one click away at any window size): the mesh as
// the 3D view shows it now (OBJ, glTF), the fold lines (SVG, CSV), and a PNG of the window, which
// the frame loop takes after drawing.
#pragma once

#include <optional>
#include <string>

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"
#include "core/geometry/geometry.hpp"

namespace foldlab::gui {

class ExportPanel {
 public:
  // The menu's contents, between ImGui::BeginMenu and EndMenu: the file stem, then one item per
  // format. Files are written relative to the working folder unless the stem is a path.
  void menu(Document& document, const ClothStyle& style);
  // The PNG path the user asked for, once.
  std::optional<std::string> take_screenshot_request();

 private:
  char stem_[256] = "foldlab-export";
  std::optional<std::string> screenshot_request_;
};

// The mesh as the 3D view shows it: with the breeze's offset at this instant when it blows
// (z exaggeration is a view aid and is not exported).
DeformedGrid mesh_as_shown(Scene& scene, const ClothStyle& style);

}  // namespace foldlab::gui
