// The Export menu (in the menu bar, so that it is one click away at any window size): the mesh as
// the 3D view shows it now (OBJ, glTF), the fold lines (SVG, CSV), and PNG pictures of the
// window, the 3D view alone or the fold plot or sweep alone, which the frame loop takes after
// drawing; and the 3D view or the fold plot alone at a size asked for in a small dialog, drawn as
// `foldlab picture` draws them (picture.hpp). Every item asks where with the save dialog.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/renderer.hpp"
#include "core/geometry/geometry.hpp"

namespace foldlab::gui {

class ExportPanel {
 public:
  struct PictureRequest {
    std::string path;
    // The view as drawn, cut from the window; none: the whole window.
    std::optional<PictureView> part;
    // A picture drawn apart from the window at its own size (the picture dialog); none: a part
    // of the window as drawn.
    std::optional<PictureSpec> spec;
  };

  // The menu's contents, between ImGui::BeginMenu and EndMenu: one item per format and per
  // picture the panels give, each opening the save dialog.
  void menu(Document& document, UiStatus& status, const ClothStyle& style, FileDialog& files,
            std::span<const std::unique_ptr<Panel>> panels);
  // The picture dialog (size, background, caption) the menu's "... any size" items open; every
  // frame, outside the menu.
  void draw_picture_dialog(UiStatus& status, FileDialog& files);
  // At the start of a frame: a picture asked for in an earlier frame may be taken after this one,
  // which draws neither the menu nor the dialog it was asked for in.
  void new_frame() { picture_ready_ = picture_.has_value(); }
  // The picture the user asked for, once, when it may be taken after this frame.
  std::optional<PictureRequest> take_picture_request();

 private:
  std::optional<std::string> picture_size_choice();
  // The files: one item per export format, and the fabric as a preset.
  void file_items(Document& document, UiStatus& status, const ClothStyle& style, FileDialog& files);
  // The pictures: of the window or a part as drawn, or of a view alone at any size.
  void picture_items(const Document& document, UiStatus& status, FileDialog& files,
                     std::span<const std::unique_ptr<Panel>> panels);

  std::optional<PictureRequest> picture_;
  bool picture_ready_ = false;
  // The picture dialog: asked to open, and what it holds (kept for the next picture).
  bool open_dialog_ = false;
  PictureSpec dialog_spec_;
  const PictureOffer* dialog_offer_ = nullptr;  // the picture the dialog is for
  std::string dialog_name_;  // the file name the any-size picture's save dialog offers
  int size_choice_ = 0;      // kPictureSizes, then custom
  // As typed, digits alone (kPictureSideDigits of them): read by read_typed_picture_size.
  char custom_width_[kPictureSideDigits + 1] = "1920";
  char custom_height_[kPictureSideDigits + 1] = "1080";
};

// The mesh as the 3D view shows it: with the breeze's offset at this instant when it blows
// (z exaggeration is a view aid and is not exported).
DeformedGrid mesh_as_shown(Scene& scene, const ClothStyle& style);

}  // namespace foldlab::gui
