#include "app/gui/panels/cloth_view_panel.hpp"

#include <algorithm>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

std::optional<std::string> ClothViewPanel::set_view(std::string_view key, std::string_view value) {
  if (key == "print") {
    if (value == "plain" || value == "checks" || value == "stripes") {
      style_.print = value == "plain"    ? ClothStyle::Print::plain
                     : value == "checks" ? ClothStyle::Print::checks
                                         : ClothStyle::Print::stripes;
      return std::nullopt;
    }
    return "print = '" + detail::cut(value) + "' is not one of: plain, checks, stripes";
  }
  const std::optional<double> number = parse_number(value);
  if (!number) {
    return detail::cut(key) + " = '" + detail::cut(value) + "' is not a number";
  }
  const float v = static_cast<float>(*number);
  if (key == "breeze") {
    style_.breeze = v != 0.0f;
  } else if (key == "breeze_mm") {
    style_.breeze_mm = v;
  } else if (key == "time") {
    style_.time_s = v;
    breeze_playing_ = false;  // a scripted picture shows that instant
  } else if (key == "z") {
    style_.z_exaggeration = std::clamp(v, 1.0f, 20.0f);
  } else if (key == "wireframe") {
    style_.wireframe = v != 0.0f;
  } else if (key == "fold_lines") {
    style_.fold_lines = v != 0.0f;
  } else if (key == "ground") {
    style_.ground = v != 0.0f;
  } else {
    return "unknown view key '" + detail::cut(key) +
           "' (known: sweep, print, breeze, breeze_mm, time, z, wireframe, fold_lines, ground)";
  }
  return std::nullopt;
}

void ClothViewPanel::settings_row() {
  ImGui::Checkbox("wireframe", &style_.wireframe);
  same_line_if_fits(checkbox_width("fold lines"));
  ImGui::Checkbox("fold lines", &style_.fold_lines);
  same_line_if_fits(checkbox_width("ground"));
  ImGui::Checkbox("ground", &style_.ground);
  same_line_if_fits(button_width("reset camera"));
}

// Reframes for a new cloth (or on request), keeping the user's direction when only the cloth's
// size changed.
void ClothViewPanel::follow_the_cloth(Scene& scene, bool reset) {
  if (reset) {
    camera_user_moved_ = false;
  }
  if (reset || !camera_framed_ ||
      (!camera_user_moved_ && camera_grid_version_ != scene.version(Stage::grid))) {
    Eigen::Vector3f centre;
    float radius = 1.0f;
    cloth_bounds(scene, centre, radius);
    const OrbitCamera previous = camera_;
    camera_.frame(centre, radius);
    if (camera_framed_ && !reset) {
      camera_.yaw_rad = previous.yaw_rad;  // keep the user's direction, refit the distance only
      camera_.pitch_rad = previous.pitch_rad;
    }
    camera_framed_ = true;
    camera_grid_version_ = scene.version(Stage::grid);
  }
}

void ClothViewPanel::draw(Document& document, Renderer& renderer) {
  if (!begin_panel("Cloth (3D)", renderer)) {
    ImGui::End();
    return;  // hidden: no grid, no normals, no upload, no draw
  }
  stale_mark(document);
  if (camera_loads_ != document.loads()) {
    camera_loads_ = document.loads();  // another preset: frame it afresh
    camera_framed_ = false;
    camera_user_moved_ = false;
  }
  settings_row();
  const bool reset = ImGui::SmallButton("reset camera");
  ImGui::SetNextItemWidth(ems(12.0f));
  ImGui::SliderFloat("z exaggeration", &style_.z_exaggeration, 1.0f, 20.0f, "x %.1f",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  help_marker(
      "Draws the out-of-plane depth z this many times deeper, to see the folds; the "
      "numbers are not changed.");
  ImGui::SetNextItemWidth(ems(7.5f));
  int print = static_cast<int>(style_.print);
  if (ImGui::Combo("print", &print, "plain\0woven checks\0stripes\0")) {
    style_.print = static_cast<ClothStyle::Print>(print);
  }
  if (style_.print != ClothStyle::Print::plain) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ems(8.5f));
    ImGui::SliderFloat("##print size", &style_.print_mm, 10.0f, 300.0f, "%.0f mm",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  }
  ImGui::SameLine();
  ImGui::Checkbox("breeze", &style_.breeze);
  if (style_.breeze) {
    ImGui::SameLine();
    if (ImGui::SmallButton(breeze_playing_ ? "pause" : "play")) {
      breeze_playing_ = !breeze_playing_;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ems(7.5f));
    ImGui::SliderFloat("##breeze", &style_.breeze_mm, 5.0f, 300.0f, "%.0f mm",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (breeze_playing_) {
      style_.time_s += ImGui::GetIO().DeltaTime;  // the solver does not run: only the shader moves
    }
  }
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const FrameSize size{std::max(16, static_cast<int>(available.x)),
                       std::max(16, static_cast<int>(available.y))};
  Scene& scene = document.scene();
  follow_the_cloth(scene, reset);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("view",
                         ImVec2(static_cast<float>(size.width), static_cast<float>(size.height)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    camera_user_moved_ = true;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
    } else {
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y, static_cast<float>(size.height));
    }
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    camera_user_moved_ = true;
    camera_.zoom(io.MouseWheel);
  }
  renderer.draw_cloth(ImGui::GetWindowDrawList(), origin, scene, camera_, size, style_);
  ImGui::GetWindowDrawList()->AddText(ImVec2(origin.x + 6, origin.y + 4),
                                      IM_COL32(200, 200, 200, 200),
                                      "drag: orbit, right-drag: pan, wheel: zoom");
  ImGui::End();
}

}  // namespace foldlab::gui
