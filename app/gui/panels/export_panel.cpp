#include "app/gui/panels/export_panel.hpp"

#include <filesystem>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"
#include "core/io/export.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/io.hpp"

namespace foldlab::gui {

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

std::optional<std::string> ExportPanel::take_screenshot_request() {
  std::optional<std::string> request;
  request.swap(screenshot_request_);
  return request;
}

void ExportPanel::menu(Document& document, const ClothStyle& style) {
  ImGui::TextUnformatted("file name (without extension)");
  ImGui::SetNextItemWidth(ems(20.0f));
  ImGui::InputText("##export stem", stem_, sizeof stem_);
  const std::string stem = stem_;
  Scene& scene = document.scene();
  const std::string& name = document.loaded().name;
  auto write = [&document](const std::string& path, auto&& make) {
    try {
      write_file_atomically(path, make());
      document.notify("Wrote " + std::filesystem::absolute(path).string(), false);
    } catch (const std::exception& e) {
      document.notify(std::string("Not exported: ") + e.what(), true);
    }
  };
  ImGui::Separator();
  if (ImGui::MenuItem("OBJ mesh (.obj)")) {
    write(stem + ".obj", [&] { return mesh_to_obj(mesh_as_shown(scene, style), name); });
  }
  if (ImGui::MenuItem("glTF mesh (.glb)")) {
    write(stem + ".glb", [&] { return mesh_to_glb(mesh_as_shown(scene, style), name); });
  }
  if (ImGui::MenuItem("Fold lines (.svg)")) {
    write(stem + ".svg",
          [&] { return fold_lines_to_svg(scene.fold_lines(), scene.solution(), name); });
  }
  if (ImGui::MenuItem("Fold lines (.csv)")) {
    write(stem + ".csv", [&] { return fold_lines_to_csv(scene.fold_lines()); });
  }
  if (ImGui::MenuItem("Window picture (.png)")) {
    screenshot_request_ = stem + ".png";
  }
}

}  // namespace foldlab::gui
