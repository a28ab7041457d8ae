#include "app/gui/panels/export_panel.hpp"

#include <filesystem>
#include <utility>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"
#include "core/io/export.hpp"
#include "core/io/export_formats.hpp"
#include "core/io/io.hpp"

namespace foldlab::gui {
namespace {

// The name the save dialog offers, before the user types another.
constexpr const char* kStem = "foldlab-export";

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

void ExportPanel::menu(Document& document, const ClothStyle& style, FileDialog& files,
                       bool sweep_shown) {
  Scene& scene = document.scene();
  const std::string& name = document.loaded().name;
  // The files are written when the dialog's answer comes, from the scene as it is then.
  const auto save_as = [&](const char* title, const char* extension, auto make) {
    files.open({FileDialog::Mode::save,
                title,
                std::string(kStem) + extension,
                {extension},
                [&document, make](const std::filesystem::path& path) -> std::optional<std::string> {
                  try {
                    write_file_atomically(path, make());
                  } catch (const std::exception& e) {
                    return std::string("Not exported: ") + e.what();
                  }
                  document.notify("Wrote " + path.string(), false);
                  return std::nullopt;
                }},
               document);
  };
  const auto picture = [&](const char* title, Picture what) {
    files.open({FileDialog::Mode::save,
                title,
                std::string(kStem) + ".png",
                {".png"},
                [this, what](const std::filesystem::path& path) -> std::optional<std::string> {
                  picture_ = PictureRequest{path.string(), what};
                  picture_ready_ = false;
                  return std::nullopt;
                }},
               document);
  };
  for (const ExportFormat& format : kExportFormats) {
    const std::string label = std::string(format.menu_label) + "...";
    if (!ImGui::MenuItem(label.c_str())) {
      continue;
    }
    const std::string title = "Export " + std::string(format.what);
    const std::string extension(format.extension);
    save_as(title.c_str(), extension.c_str(), [&scene, style, name, &format] {
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
    });
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Window picture (.png)...")) {
    picture("Export window picture", Picture::window);
  }
  if (ImGui::MenuItem("3D view picture (.png)...")) {
    picture("Export 3D view picture", Picture::cloth_view);
  }
  if (ImGui::MenuItem("Fold plot picture (.png)...")) {
    picture("Export fold plot picture", Picture::fold_plot);
  }
  if (ImGui::MenuItem("Sweep picture (.png)...", nullptr, false, sweep_shown)) {
    picture("Export sweep picture", Picture::sweep);
  }
  if (!sweep_shown && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Open Analysis > Sweep to take its plots.");
  }
}

}  // namespace foldlab::gui
