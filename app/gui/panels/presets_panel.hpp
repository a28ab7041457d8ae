// The Presets panel: the shipped and the user's presets (a click loads one, asking first when
// that would replace unsaved edits), "Save as..." with an overwrite question, Ctrl+S, and the
// document's status line, the calibration window's button and the question before unsaved edits
// are replaced ("Save / Discard / Cancel").
#pragma once

#include "app/common/presets_dir.hpp"

#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"

namespace foldlab::gui {

class PresetsPanel : public Panel {
 public:
  PresetsPanel(std::filesystem::path presets_dir, std::filesystem::path user_presets_dir);
  const char* name() const override { return "Presets"; }
  const char* introduction() const override {
    return "the paper's own cases and a few fabrics to start from.";
  }
  const char* key() const override { return "presets"; }
  void draw(PanelContext& context) override;
  // Why the listing is not the whole folder (too many presets), said as notices.
  void session_read(PanelContext& context) override;
  // Ctrl+S, unless a dialog or a widget being dragged or typed into has the keys.
  void begin_frame(PanelContext& context) override;
  // The save dialogs and the unsaved edits' question, over every panel; a preset the photo's fit
  // saved joins the list.
  void end_frame(PanelContext& context) override;
  // The user's own presets as listed ("user_presets": what "Save as..." kept).
  void report(nlohmann::json& state, PanelContext& context) const override;
  // Saves the current valid parameters as a user preset named `name` (the file name is its slug);
  // asks before replacing a file unless `overwrite`.
  void save_as(Document& document, UiStatus& status, const std::string& name, bool overwrite);
  // Ctrl+S: over the loaded preset when it is one of the user's, else opens "Save as". Asks first
  // (unless `confirmed_over_b`) when B was pinned from that file and A's values are not B's.
  void save(Document& document, UiStatus& status, bool confirmed_over_b = false);
  // Whether saving A over its file would leave B, pinned from that file, unlike it.
  static bool saves_over_pinned_b(Document& document);
  // The overwrite question and "Save as", shown while the document names them as its modal;
  // drawn outside any panel so that they open whether or not the panel is visible.
  void draw_dialogs(Document& document, UiStatus& status);
  static constexpr const char* kOverwriteModal = "Overwrite preset?";
  static constexpr const char* kSaveAsModal = "Save as";
  // Ctrl+S over the file B was pinned from, with values that are not B's.
  static constexpr const char* kPinnedFileModal = "Save over B's preset?";
  // The file dialog's title for "Open file...": a preset file from anywhere on the disk.
  static constexpr const char* kOpenFileModal = "Open a preset file";

  struct Entry {
    std::string name;
    std::string description;  // shown on hover, with the preset it was derived from
    std::filesystem::path path;
    bool user = false;
  };
  const std::vector<Entry>& entries() const { return entries_; }
  // Why the listing is not the whole folder (too many presets); the explorer shows them as notices.
  const std::vector<std::string>& notices() const { return notices_; }
  // Reads the folders again (a preset was written elsewhere).
  void refresh();

 private:
  bool is_user_preset(const std::string& path) const;
  // Writes the valid parameters as preset `name` to `path`, then goes on with what waited for
  // the save (a preset load after "Save" in the unsaved-changes question).
  void write(Document& document, UiStatus& status, const std::string& name,
             const std::filesystem::path& path);
  // The list of presets, shipped then the user's, `height_px` high; a click loads one.
  void draw_list(Document& document, float height_px);
  static float notices_height_px(const UiStatus& status);
  void draw_messages(UiStatus& status);
  // "Save / Discard / Cancel" before a preset load replaces unsaved edits.
  void draw_unsaved_dialog(Document& document, UiStatus& status);

  std::filesystem::path presets_dir_;
  std::filesystem::path user_presets_dir_;
  std::vector<Entry> entries_;
  std::vector<std::string> notices_;
  char save_name_[128] = {};
  char save_as_name_[128] = {};
  std::string pending_overwrite_;  // name waiting for the user's "overwrite?" answer
  float below_list_px_ = 0.0f;     // the height of what was drawn under the list in the last frame
};

using app::preset_slug;

// The preset that saving the document's last valid inputs under `name` writes: the loaded one's
// own when the name is kept, else one derived from it.
Preset preset_to_save(const Document& document, const std::string& name);

}  // namespace foldlab::gui
