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

// Per view (in PictureView's order): what the picture dialog says it draws, the save dialog's
// title, and the words the offered file name gives it.
struct PictureViewWords {
  PictureView view;
  const char* text;
  const char* title;
  const char* file_words;
};
constexpr PictureViewWords kPictureViewWords[] = {
    {PictureView::cloth, "The 3D view's cloth alone, as the view shows it now.",
     "Export 3D view picture", "3d-view"},
    {PictureView::fold_plot, "The fold plot alone, millimetres alike across and down.",
     "Export fold plot picture", "fold-plot"},
    {PictureView::sweep,
     "The sweep's n, Q and z_max over the input and range the Sweep tab has now.",
     "Export sweep picture", "sweep"},
    {PictureView::compare, "A and B side by side, as the 3D view shows them now.",
     "Export A and B picture", "a-and-b"},
};
constexpr bool in_view_order() {
  for (std::size_t i = 0; i < std::size(kPictureViewWords); ++i) {
    if (static_cast<std::size_t>(kPictureViewWords[i].view) != i) {
      return false;
    }
  }
  return std::size(kPictureViewWords) == static_cast<std::size_t>(PictureView::compare) + 1;
}
static_assert(in_view_order());
const PictureViewWords& words_of(PictureView view) {
  return kPictureViewWords[static_cast<std::size_t>(view)];
}

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
                       FileDialog& files, bool sweep_shown) {
  file_items(document, status, style, files);
  ImGui::Separator();
  picture_items(document, status, files, sweep_shown);
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
                                bool sweep_shown) {
  const auto picture = [&](const char* title, Picture what, std::string_view words) {
    files.open({FileDialog::Mode::save,
                title,
                offered_name(document, words, ".png"),
                {".png"},
                [this, what](const std::filesystem::path& path) -> std::optional<std::string> {
                  picture_ = PictureRequest{path.string(), what, std::nullopt};
                  picture_ready_ = false;
                  return std::nullopt;
                }},
               status);
  };
  if (ImGui::MenuItem("Window picture (.png)...")) {
    picture("Export window picture", Picture::window, "window");
  }
  if (ImGui::MenuItem("3D view picture (.png)...")) {
    picture("Export 3D view picture", Picture::cloth_view, "3d-view");
  }
  if (ImGui::MenuItem("Fold plot picture (.png)...")) {
    picture("Export fold plot picture", Picture::fold_plot, "fold-plot");
  }
  const auto any_size = [&](const char* label, PictureView view, bool enabled = true) {
    if (ImGui::MenuItem(label, nullptr, false, enabled)) {
      dialog_spec_.view = view;
      dialog_name_ = offered_name(document, words_of(view).file_words, ".png");
      open_dialog_ = true;
    }
  };
  any_size("3D view picture, any size (.png)...", PictureView::cloth);
  any_size("Fold plot picture, any size (.png)...", PictureView::fold_plot);
  any_size("Sweep picture, any size (.png)...", PictureView::sweep);
  const bool pinned = document.compare().pinned();
  any_size("A and B picture, any size (.png)...", PictureView::compare, pinned);
  if (!pinned && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Pin a fabric as B first (Compare > Pin as B).");
  }
  if (ImGui::MenuItem("Sweep picture (.png)...", nullptr, false, sweep_shown)) {
    picture("Export sweep picture", Picture::sweep, "sweep-plots");
  }
  if (!sweep_shown && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Open Analysis > Sweep to take its plots.");
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
  ImGui::TextUnformatted(words_of(dialog_spec_.view).text);
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
  if (ImGui::Button("Cancel")) {
    ImGui::CloseCurrentPopup();
  }
  if (save) {
    ImGui::CloseCurrentPopup();
    const PictureSpec spec = dialog_spec_;
    files.open({FileDialog::Mode::save,
                words_of(spec.view).title,
                dialog_name_,
                {".png"},
                [this, spec](const std::filesystem::path& path) -> std::optional<std::string> {
                  picture_ = PictureRequest{path.string(), Picture::window, spec};
                  picture_ready_ = false;
                  return std::nullopt;
                }},
               status);
  }
  ImGui::EndPopup();
}

}  // namespace foldlab::gui
