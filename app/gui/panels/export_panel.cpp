#include "app/gui/panels/export_panel.hpp"

#include <filesystem>
#include <functional>
#include <iterator>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/io/export.hpp"
#include "core/io/export_formats.hpp"
#include "core/io/io.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {
namespace {

// The name the save dialog offers, before the user types another: the fabric's name as a file
// name (cut at a word to 40 characters) and what the file holds, so that a mood board's files
// tell apart ("linen-medium-weight-3d-view.png").
std::string offered_name(const Document& document, std::string_view what,
                         std::string_view extension) {
  constexpr std::size_t kLongest = 40;
  std::string stem = preset_slug(document.loaded().name);
  if (stem.size() > kLongest) {
    const std::size_t cut = stem.rfind('-', kLongest);
    stem.resize(cut == std::string::npos || cut == 0 ? kLongest : cut);
  }
  return (stem.empty() ? std::string("foldlab") : stem) + "-" + std::string(what) +
         std::string(extension);
}

constexpr const char* kPictureDialog = "Picture";

// The sizes the picture dialog offers before "custom": a screen, a slide, a print.
struct PictureSize {
  const char* label;
  FrameSize size;
};
constexpr PictureSize kPictureSizes[] = {{"1920 x 1080 (full HD)", {1920, 1080}},
                                         {"3000 x 2000", {3000, 2000}},
                                         {"A4 at 300 dpi (3508 x 2480)", {3508, 2480}}};
constexpr int kCustomSize = static_cast<int>(std::size(kPictureSizes));

}  // namespace

DeformedGrid mesh_as_shown(Scene& scene, const ClothStyle& style) {
  scene.normals();
  DeformedGrid grid = scene.grid();
  if (style.breeze) {
    const float depth =
        static_cast<float>(lowest_point_mm(scene.solution(), scene.parameters().hanging.height_mm));
    for (Eigen::Vector3f& v : grid.positions_mm) {
      v += breeze_offset(v, depth, style.breeze_mm, style.time_s);
    }
    grid.normals = vertex_normals(grid.positions_mm, grid.triangle_indices);
  }
  return grid;
}

std::optional<ExportPanel::PictureRequest> ExportPanel::take_picture_request() {
  if (!picture_ready_) {
    return std::nullopt;
  }
  picture_ready_ = false;
  return std::exchange(picture_, std::nullopt);
}

namespace {

// The save dialog's answer for a file made by `write`: written at the chosen path and said in the
// status line, or the reason it was not.
FileDialog::Chosen write_and_say(UiStatus& status,
                                 std::function<void(const std::filesystem::path&)> write) {
  return [&status, write = std::move(write)](
             const std::filesystem::path& path) -> std::optional<std::string> {
    try {
      write(path);
    } catch (const std::exception& e) {
      return std::string("Not exported: ") + e.what();
    }
    status.notify("Wrote " + path.string(), false);
    return std::nullopt;
  };
}

}  // namespace

void ExportPanel::menu(Document& document, UiStatus& status, const ClothStyle& style,
                       FileDialog& files, std::span<const std::unique_ptr<Panel>> panels) {
  file_items(document, status, style, files);
  ImGui::Separator();
  picture_items(document, status, files, panels);
}

void ExportPanel::file_items(Document& document, UiStatus& status, const ClothStyle& style,
                             FileDialog& files) {
  Scene& scene = document.scene();
  const std::string& name = document.loaded().name;
  for (const ExportFormat& format : kExportFormats) {
    const std::string label = std::string(format.menu_label) + "...";
    if (!ImGui::MenuItem(label.c_str())) {
      continue;
    }
    const std::string extension(format.extension);
    // The file is written when the dialog's answer comes, from the scene as it is then.
    const auto make = [&scene, style, name, &format] {
      // The mesh as the 3D view shows it (with the breeze), built only for a mesh format.
      DeformedGrid mesh;
      ExportSource source{.title = name};
      if (format.content == ExportFormat::Content::mesh) {
        mesh = mesh_as_shown(scene, style);
        source.mesh = &mesh;
      } else {
        source.lines = &scene.fold_lines();
        source.solution = &scene.solution();
      }
      return format.write(source);
    };
    files.open({FileDialog::Mode::save,
                "Export " + std::string(format.what),
                offered_name(document,
                             format.content == ExportFormat::Content::mesh ? "cloth" : "fold-lines",
                             extension),
                {extension},
                write_and_say(status,
                              [make](const std::filesystem::path& path) {
                                write_file_atomically(path, make());
                              })},
               status);
  }
  if (ImGui::MenuItem("Preset (.json)...")) {
    // The fabric as a preset file to keep or send, named after the file.
    files.open({FileDialog::Mode::save,
                "Export the fabric as a preset",
                preset_slug(document.loaded().name) + ".json",
                {".json"},
                write_and_say(status,
                              [&document](const std::filesystem::path& path) {
                                save_preset(preset_to_save(document, path.stem().string()), path);
                              })},
               status);
  }
}

void ExportPanel::picture_items(const Document& document, UiStatus& status, FileDialog& files,
                                std::span<const std::unique_ptr<Panel>> panels) {
  const auto picture = [&](const char* title, std::optional<PictureView> part,
                           std::string_view words) {
    files.open({FileDialog::Mode::save,
                title,
                offered_name(document, words, ".png"),
                {".png"},
                [this, part](const std::filesystem::path& path) -> std::optional<std::string> {
                  picture_ = PictureRequest{path.string(), part, std::nullopt};
                  picture_ready_ = false;
                  return std::nullopt;
                }},
               status);
  };
  // An item greyed while its panel cannot give the picture, saying why when hovered.
  const auto offered = [&](const Panel& panel, const PictureOffer& offer, const char* label,
                           bool as_drawn) {
    const std::optional<std::string> unavailable =
        panel.picture_unavailable(offer.view, document, as_drawn);
    const bool chosen = ImGui::MenuItem(label, nullptr, false, !unavailable);
    if (unavailable && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip("%s", unavailable->c_str());
    }
    return chosen;
  };
  if (ImGui::MenuItem("Window picture (.png)...")) {
    picture("Export window picture", std::nullopt, "window");
  }
  for (const std::unique_ptr<Panel>& panel : panels) {
    for (const PictureOffer& offer : panel->pictures()) {
      if (offer.window_item != nullptr && offered(*panel, offer, offer.window_item, true)) {
        picture(offer.title, offer.view, offer.file_word);
      }
    }
  }
  for (const std::unique_ptr<Panel>& panel : panels) {
    for (const PictureOffer& offer : panel->pictures()) {
      if (offered(*panel, offer, offer.any_size_item, false)) {
        dialog_spec_.view = offer.view;
        dialog_offer_ = &offer;
        dialog_name_ = offered_name(document, offer.file_word, ".png");
        open_dialog_ = true;
      }
    }
  }
}

// The size radio buttons and the custom size typed; the reason a typed size is refused.
std::optional<std::string> ExportPanel::picture_size_choice() {
  ImGui::TextUnformatted("Size (pixels)");
  for (int i = 0; i < kCustomSize; ++i) {
    ImGui::RadioButton(kPictureSizes[i].label, &size_choice_, i);
  }
  ImGui::RadioButton("custom", &size_choice_, kCustomSize);
  std::optional<std::string> problem;
  if (size_choice_ == kCustomSize) {
    // Text, not ImGui's InputInt: that reads a long number into an int, wrapped around to a
    // negative size. Only digits get in, and no more than a side can need.
    const auto digits_only = [](ImGuiInputTextCallbackData* data) {
      return data->EventChar >= '0' && data->EventChar <= '9' ? 0 : 1;
    };
    ImGui::SetNextItemWidth(ems(6.0f));
    ImGui::InputText("width", custom_width_, sizeof custom_width_,
                     ImGuiInputTextFlags_CallbackCharFilter, digits_only);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ems(6.0f));
    ImGui::InputText("height", custom_height_, sizeof custom_height_,
                     ImGuiInputTextFlags_CallbackCharFilter, digits_only);
    const TypedPictureSize typed = read_typed_picture_size(custom_width_, custom_height_);
    if (typed.size) {
      dialog_spec_.size = *typed.size;
    } else {
      problem = typed.problem;
    }
  } else {
    dialog_spec_.size = kPictureSizes[size_choice_].size;
  }
  return problem;
}

void ExportPanel::draw_picture_dialog(UiStatus& status, FileDialog& files) {
  if (open_dialog_) {
    ImGui::OpenPopup(kPictureDialog);
    open_dialog_ = false;
  }
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kPictureDialog, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    return;
  }
  ImGui::TextUnformatted(dialog_offer_->dialog_words);
  std::optional<std::string> problem = picture_size_choice();
  ImGui::TextUnformatted("Background");
  int background = static_cast<int>(dialog_spec_.background);
  ImGui::RadioButton("white", &background, static_cast<int>(PictureBackground::white));
  ImGui::SameLine();
  ImGui::RadioButton("transparent", &background, static_cast<int>(PictureBackground::transparent));
  ImGui::SameLine();
  ImGui::RadioButton("dark", &background, static_cast<int>(PictureBackground::dark));
  dialog_spec_.background = static_cast<PictureBackground>(background);
  ImGui::Checkbox("caption (fabric, n, Q, z_max, inputs)", &dialog_spec_.caption);
  if (dialog_spec_.view == PictureView::fold_plot) {
    ImGui::Checkbox("legend", &dialog_spec_.legend);
  }
  if (!problem) {
    problem = picture_size_problem(dialog_spec_.size);
  }
  if (problem) {
    ImGui::PushTextWrapPos(ems(24.0f));
    ImGui::TextColored(kErrorText, "%s", problem->c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::BeginDisabled(problem.has_value());
  const bool save = ImGui::Button("Save as...");
  ImGui::EndDisabled();
  ImGui::SameLine();
  // Escape cancels, as it does every other dialog (unless a size being typed takes it back).
  if (ImGui::Button("Cancel") ||
      (!ImGui::IsAnyItemActive() &&
       ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))) {
    ImGui::CloseCurrentPopup();
  }
  if (save) {
    ImGui::CloseCurrentPopup();
    const PictureSpec spec = dialog_spec_;
    files.open({FileDialog::Mode::save,
                dialog_offer_->title,
                dialog_name_,
                {".png"},
                [this, spec](const std::filesystem::path& path) -> std::optional<std::string> {
                  picture_ = PictureRequest{path.string(), std::nullopt, spec};
                  picture_ready_ = false;
                  return std::nullopt;
                }},
               status);
  }
  ImGui::EndPopup();
}

}  // namespace foldlab::gui
