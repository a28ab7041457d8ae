#include "app/gui/panels/presets_panel.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <system_error>
#include <utility>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/presets_dir.hpp"
#include "app/common/version.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/panels/calibration_panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/photo_overlay.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/session.hpp"
#include "core/io/link.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

PresetsPanel::PresetsPanel(std::filesystem::path presets_dir,
                           std::filesystem::path user_presets_dir)
    : presets_dir_(std::move(presets_dir)), user_presets_dir_(std::move(user_presets_dir)) {
  refresh();
}

void PresetsPanel::refresh() {
  entries_.clear();
  auto add_folder = [this](const std::filesystem::path& dir, bool user) {
    if (dir.empty()) {
      return;
    }
    std::vector<std::filesystem::path> files = app::preset_files(dir);
    if (files.size() > kMaxListedPresets) {
      const std::string notice =
          detail::printf_string("%zu presets in %s; listing the first %zu.", files.size(),
                                dir.string().c_str(), kMaxListedPresets);
      if (std::find(notices_.begin(), notices_.end(), notice) == notices_.end()) {
        notices_.push_back(notice);
      }
      files.resize(kMaxListedPresets);
    }
    for (const auto& file : files) {
      Entry entry{file.stem().string(), {}, file, user};
      if (oversized_file(file, kMaxListedPresetBytes)) {
        entry.name = file.filename().string() + " (too large to read)";
      } else {
        try {
          const Preset preset = load_preset(file);
          entry.name = preset.name;
          entry.description = preset.description;
          if (!preset.derived_from.empty()) {
            entry.description += (entry.description.empty() ? "" : "\n") +
                                 std::string("Derived from \"") + preset.derived_from + "\".";
          }
        } catch (const PresetError&) {
          entry.name = file.filename().string() + " (unreadable)";
        }
      }
      entries_.push_back(std::move(entry));
    }
  };
  add_folder(presets_dir_, false);
  add_folder(user_presets_dir_, true);
}

namespace {

// A preset holds only values the model accepts: saved with refused inputs on screen, the file
// would hold the last valid ones while the sliders show others. Says so, and drops a load that
// waited for the save (the edits stay).
bool refused_inputs_stop_the_save(Document& document, UiStatus& status) {
  const std::optional<std::string> refusal = document.refusal();
  if (!refusal) {
    return false;
  }
  document.cancel_replace();
  status.notify("Not saved: a preset holds only accepted values, and these are refused:\n" +
                    *refusal + "\nChange them, or undo (Ctrl+Z), then save.",
                MessageKind::error);
  return true;
}

}  // namespace

void PresetsPanel::save_as(Document& document, UiStatus& status, const std::string& name,
                           bool overwrite) {
  if (refused_inputs_stop_the_save(document, status)) {
    return;
  }
  const std::string file = preset_slug(name);
  if (file.empty()) {
    status.notify("Give the preset a name with at least one letter or digit.", true);
    return;
  }
  // Two entries of one name in the list could not be told apart, and Ctrl+S on the user's would
  // look like saving over the shipped one.
  const bool shipped_name = std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return !e.user && preset_slug(e.name) == file;
  });
  if (shipped_name) {
    status.notify("\"" + name + "\" is the name of a shipped preset; give yours another name.",
                  MessageKind::error);
    status.set_modal(kSaveAsModal);  // the name stays typed, to be changed
    return;
  }
  const std::filesystem::path path = user_presets_dir_ / (file + ".json");
  if (!overwrite && std::filesystem::exists(path)) {
    pending_overwrite_ = name;
    status.set_modal(kOverwriteModal);
    return;
  }
  write(document, status, name, path);
}

bool PresetsPanel::is_user_preset(const std::string& path) const {
  if (path.empty() || user_presets_dir_.empty()) {
    return false;
  }
  std::error_code error;
  return std::filesystem::equivalent(std::filesystem::path(path).parent_path(), user_presets_dir_,
                                     error);
}

bool PresetsPanel::saves_over_pinned_b(Document& document) {
  Comparison& compare = document.compare();
  if (!compare.pinned() || compare.b_origin_path().empty()) {
    return false;
  }
  std::error_code error;
  return std::filesystem::equivalent(compare.b_origin_path(), document.loaded_path(), error) &&
         (!(compare.b().parameters == document.scene().parameters()) ||
          !(compare.b().appearance == document.appearance()));
}

void PresetsPanel::save(Document& document, UiStatus& status, bool confirmed_over_b) {
  if (refused_inputs_stop_the_save(document, status)) {
    return;
  }
  if (is_user_preset(document.loaded_path())) {
    if (!confirmed_over_b && saves_over_pinned_b(document)) {
      status.set_modal(kPinnedFileModal);  // the pinned fabric would no longer match its file
      return;
    }
    write(document, status, document.loaded().name, document.loaded_path());
    return;
  }
  const std::string suggestion = document.loaded().name + " (edited)";
  std::snprintf(save_as_name_, sizeof save_as_name_, "%s", suggestion.c_str());
  status.set_modal(kSaveAsModal);
}

Preset preset_to_save(const Document& document, const std::string& name) {
  const Preset& loaded = document.loaded();
  Preset preset = loaded;
  preset.name = name;
  preset.parameters = document.scene().parameters();
  // A dragged value is saved as the slider shows it, which the user can read back and type
  // again; a typed one exactly. Not when the rounding is refused (a value at a range's end).
  const Parameters shown = with_shown_digits(preset.parameters, document.dragged_keys());
  if (validate(shown).empty()) {
    preset.parameters = shown;
  }
  preset.appearance = document.appearance();
  if (loaded.name != name) {
    // The source preset's description and sources describe its fabric, not this one: the new
    // preset names where it came from instead, and that preset's file keeps its sources.
    preset.derived_from = loaded.name;
    preset.description = "Saved from FoldLab with edited inputs.";
    preset.source = {};
    preset.published = {};  // published results belong to the paper's case, not to an edit
  }
  preset.written_by = app::version_line();
  return preset;
}

void PresetsPanel::write(Document& document, UiStatus& status, const std::string& name,
                         const std::filesystem::path& path) {
  const Preset preset = preset_to_save(document, name);
  try {
    std::filesystem::create_directories(path.parent_path());
    save_preset(preset, path);
    if (document.edited() == document.scene().parameters() &&
        document.edited() != preset.parameters) {
      // The edits become what was saved (dragged values at the slider's digits), so that the
      // file and the fabric shown agree and nothing reads as unsaved.
      document.apply(Edit::replace(preset.parameters));
    }
    document.adopt(preset, path.string());
    status.notify("Saved to " + path.string(), MessageKind::success);
    refresh();
  } catch (const std::exception& e) {
    document.cancel_replace();  // what waited for the save must not replace unsaved edits
    status.notify(std::string("Not saved: ") + e.what(), MessageKind::error);
    return;
  }
  document.continue_replace();
}

void PresetsPanel::draw_dialogs(Document& document, UiStatus& status) {
  const std::string& modal = status.modal_title();
  if (modal != kOverwriteModal && modal != kSaveAsModal && modal != kPinnedFileModal) {
    return;
  }
  if (!ImGui::IsPopupOpen(modal.c_str())) {
    ImGui::OpenPopup(modal.c_str());
  }
  const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  const auto cancel = [&document, &status] {
    status.set_modal("");
    ImGui::CloseCurrentPopup();
    document.cancel_replace();
    status.notify("Not saved.", MessageKind::warning);
  };
  if (ImGui::BeginPopupModal(kPinnedFileModal, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const Comparison& compare = document.compare();
    ImGui::Text("B, \"%s\", was pinned from this preset's file.",
                compare.pinned() ? compare.b().name.c_str() : "");
    ImGui::TextUnformatted(
        "Saving A's values there leaves B different from the file it came "
        "from; A as a new preset keeps both.");
    if (ImGui::Button("Save over it")) {
      status.set_modal("");
      ImGui::CloseCurrentPopup();
      save(document, status, true);
    }
    ImGui::SameLine();
    if (ImGui::Button("Save A as...")) {
      ImGui::CloseCurrentPopup();
      const std::string suggestion = document.loaded().name + " (edited)";
      std::snprintf(save_as_name_, sizeof save_as_name_, "%s", suggestion.c_str());
      status.set_modal(kSaveAsModal);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape) {
      cancel();
    }
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopupModal(kOverwriteModal, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("A preset named \"%s\" exists. Replace it?", pending_overwrite_.c_str());
    if (ImGui::Button("Replace")) {
      status.set_modal("");
      ImGui::CloseCurrentPopup();
      save_as(document, status, pending_overwrite_, true);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape) {
      cancel();
    }
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopupModal(kSaveAsModal, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted("Save the current parameters as a new preset named:");
    if (ImGui::IsWindowAppearing()) {
      ImGui::SetKeyboardFocusHere();
    }
    ImGui::SetNextItemWidth(ems(24.0f));
    const bool entered = ImGui::InputText("##save as name", save_as_name_, sizeof save_as_name_,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TextDisabled("in %s", user_presets_dir_.string().c_str());
    if (ImGui::Button("Save") || entered) {
      status.set_modal("");
      ImGui::CloseCurrentPopup();
      save_as(document, status, save_as_name_, false);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape) {
      cancel();
    }
    ImGui::EndPopup();
  }
}

void PresetsPanel::draw_list(Document& document, float height_px) {
  if (ImGui::BeginChild("preset list", ImVec2(0.0f, height_px), true)) {
    begin_touch_rows();
    bool user_header = false;
    for (const Entry& entry : entries_) {
      if (entry.user && !user_header) {
        ImGui::Separator();
        ImGui::TextDisabled("your presets (%s)", user_presets_dir_.string().c_str());
        user_header = true;
      }
      const bool current = entry.path.string() == document.loaded_path();
      // Wrapped at spaces rather than cut where the list's window clips it; the id stays the
      // name's.
      const float visible =
          ImGui::GetWindowDrawList()->GetClipRectMax().x - ImGui::GetCursorScreenPos().x;
      const std::string label = wrap_at_spaces(entry.name, visible) + "##" + entry.name;
      if (ImGui::Selectable(label.c_str(), current)) {
        document.replace_edits("Loading \"" + entry.name + "\" replaces them.",
                               [path = entry.path](Document& d) { d.load_preset_file(path); });
      }
      if (ImGui::IsItemHovered()) {
        const bool cut = ImGui::GetItemRectSize().x < ImGui::CalcTextSize(entry.name.c_str()).x;
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
        if (cut) {
          ImGui::TextUnformatted(entry.name.c_str());  // the whole name the list cuts
          ImGui::Separator();
        }
        ImGui::TextUnformatted(entry.description.empty() ? "(no description)"
                                                         : entry.description.c_str());
        ImGui::PopTextWrapPos();
        ImGui::TextColored(kDimText, "%s", entry.path.string().c_str());
        ImGui::EndTooltip();
      }
    }
    end_touch_rows();
  }
  ImGui::EndChild();
}

// What the notices take in draw_messages: each one's lines at the panel's width.
float PresetsPanel::notices_height_px(const UiStatus& status) {
  const float width = ImGui::GetContentRegionAvail().x;
  float height = 0.0f;
  for (const std::string& notice : status.notices()) {
    height += ImGui::CalcTextSize(wrap_at_spaces(notice, width).c_str()).y +
              ImGui::GetStyle().ItemSpacing.y;
  }
  return height;
}

// The status line and the notices, at the panel's foot under the buttons.
void PresetsPanel::draw_messages(UiStatus& status) {
  if (!status.message().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, message_colour(status.message_kind()));
    wrapped_text("%s", status.message().c_str());
    ImGui::PopStyleColor();
  }
  for (const std::string& notice : status.notices()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    wrapped_text("%s", notice.c_str());
    ImGui::PopStyleColor();
  }
}

constexpr float kLeastNameFieldEms = 7.0f;

void PresetsPanel::draw(PanelContext& context) {
  UiStatus& status = context.status;
  Document& document = context.document;
  if (!begin(context.renderer)) {
    ImGui::End();
    return;
  }
  // The list gives way to what is under it, so that "Fit to measurements..." stays in view rather
  // than under the panel's edge: the rows as they were last drawn, the notices, and two lines
  // kept for the status line at the panel's foot. The list's height does not follow the status
  // line, which comes and goes by itself: the name field and the buttons under the list never
  // move under a click when "Loaded ..." fades (a click meant for the field loaded a preset).
  for (const std::string& notice : notices_) {
    status.add_notice(notice);  // a listing refreshed by "Save as..." may be newly capped
  }
  if (below_list_px_ <= 0.0f) {
    below_list_px_ = 3.2f * ImGui::GetFrameHeightWithSpacing();
  }
  const float status_lines_px = 2.0f * ImGui::GetTextLineHeightWithSpacing();
  const float list_height = std::max(60.0f, ImGui::GetContentRegionAvail().y - below_list_px_ -
                                                notices_height_px(status) - status_lines_px);
  draw_list(document, list_height);
  float below_list_start = ImGui::GetCursorPosY();
  const float buttons = button_width("Save as...") + button_width("Open file...") +
                        2.0f * ImGui::GetStyle().ItemSpacing.x;
  // Too narrow a field beside the buttons to read a name in: it takes a line of its own.
  const bool field_beside = ImGui::GetContentRegionAvail().x - buttons >= ems(kLeastNameFieldEms);
  ImGui::SetNextItemWidth(field_beside ? -buttons : -1.0f);
  ImGui::InputTextWithHint("##save name", "name of the new preset", save_name_, sizeof save_name_);
  if (field_beside) {
    ImGui::SameLine();
  }
  if (ImGui::Button("Save as...")) {
    save_as(document, status, save_name_, false);
  }
  ImGui::SameLine();
  if (ImGui::Button("Open file...")) {
    // A preset file from anywhere, read as one from the list is (and refused in its words).
    context.files.open({FileDialog::Mode::open,
                        kOpenFileModal,
                        "",
                        {".json"},
                        [&document](const std::filesystem::path& path) {
                          document.replace_edits(
                              "Loading " + path.filename().string() + " replaces them.",
                              [path](Document& d) { d.load_preset_file(path); });
                          return std::optional<std::string>();
                        }},
                       status);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("A preset file (.json) from elsewhere: a colleague's, or one you saved.");
  }
  context.panel<CalibrationPanel>().open_button(document.scene().parameters());
  if (const std::string& note = context.appearance.notice(); !note.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
    wrapped_text("%s", note.c_str());
    ImGui::PopStyleColor();
  }
  below_list_px_ = ImGui::GetCursorPosY() - below_list_start;
  draw_messages(status);
  ImGui::End();
}

void PresetsPanel::session_read(PanelContext& context) {
  for (const std::string& notice : notices_) {
    context.status.add_notice(notice);
  }
}

// Letters by the platform's key codes: GLFW's, which are the upper-case ASCII codes.
void PresetsPanel::begin_frame(PanelContext& context) {
  const ImGuiIO& io = ImGui::GetIO();
  if (context.status.modal_title().empty() && !ImGui::IsAnyItemActive() && io.KeyCtrl &&
      !io.KeyAlt && ImGui::IsKeyPressed('S', false)) {
    save(context.document, context.status);
  }
}

void PresetsPanel::end_frame(PanelContext& context) {
  draw_unsaved_dialog(context.document, context.status);
  draw_dialogs(context.document, context.status);
  if (context.panel<PhotoOverlay>().take_saved_preset()) {
    refresh();
  }
}

void PresetsPanel::draw_unsaved_dialog(Document& document, UiStatus& status) {
  const char* title = UiStatus::kUnsavedModal;
  if (status.modal_title() != title) {
    return;
  }
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
  }
  const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Your edits of \"%s\" are not saved.", document.loaded().name.c_str());
    ImGui::TextUnformatted(document.pending_replacement().c_str());
    if (ImGui::Button("Save")) {
      ImGui::CloseCurrentPopup();
      status.set_modal("");
      save(document, status);  // then loads, unless it asks for a name or fails
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      ImGui::CloseCurrentPopup();
      document.discard_and_replace();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape) {
      ImGui::CloseCurrentPopup();
      document.cancel_replace();
      status.notify("Cancelled; your edits are kept.", MessageKind::info);
    }
    ImGui::EndPopup();
  }
}

void PresetsPanel::report(nlohmann::json& state, PanelContext& /*context*/) const {
  nlohmann::json user_presets = nlohmann::json::array();
  for (const Entry& entry : entries_) {
    if (entry.user) {
      user_presets.push_back(entry.name);
    }
  }
  state["user_presets"] = user_presets;
}

}  // namespace foldlab::gui
