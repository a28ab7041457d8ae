#include "app/gui/scripted_run.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numeric>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "core/analysis/sweep.hpp"
#include "core/io/report.hpp"
#include "core/io/scene_report.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
ScriptedRun::ScriptedRun(int frames, std::optional<AnimatedInput> animation,
                         std::optional<InputPlayer> player, std::string final_screenshot,
                         std::vector<app::NamedPath> input_files)
    : frames_(frames),
      animation_(std::move(animation)),
      player_(std::move(player)),
      final_screenshot_(std::move(final_screenshot)),
      input_files_(std::move(input_files)),
      deadline_(std::chrono::steady_clock::now() + std::chrono::seconds(30)) {}

bool ScriptedRun::wants_frame(int frame, const Explorer& explorer) {
  if (frames_ == 0) {
    return true;
  }
  // An input played every frame keeps a view that follows it busy for good: the run is its
  // frames, not the 30 s of waiting for a rest that does not come.
  if (frame + 1 == frames_ + extra_frames_ && !animation_ && explorer.busy() &&
      std::chrono::steady_clock::now() < deadline_) {
    ++extra_frames_;
  }
  return frame < frames_ + extra_frames_;
}

bool ScriptedRun::before_frame(Explorer& explorer, Surface& surface, int frame) {
  if (player_) {
    if (!player_->before_new_frame(ImGui::GetIO(), explorer)) {
      return false;
    }
    if (const std::optional<FrameSize> size = player_->take_resize_request()) {
      surface.resize(*size);
    }
  }
  if (frames_ > 0) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
  }
  if (animation_) {
    explorer.set_input(animation_->key(), animation_->value(frame));
  }
  return true;
}

void ScriptedRun::after_render(Explorer& explorer, Renderer& renderer, FrameSize size, int frame) {
  if (is_last(frame) && !final_screenshot_.empty()) {
    write_png(final_screenshot_.c_str(), size, renderer.read_pixels(size));
  }
  const std::optional<std::string> path =
      player_ ? player_->take_screenshot_request() : std::nullopt;
  if (!path) {
    return;
  }
  // The script's paths are known only as it plays, and a photo or swatch may have been loaded by
  // an earlier step: checked against every file the run has read, before writing.
  std::vector<app::NamedPath> inputs = input_files_;
  for (const app::NamedPath& open : explorer.files_in_use()) {
    inputs.push_back(open);
  }
  app::check_outputs({{"the --play script's screenshot step", *path}}, inputs);
  write_png(path->c_str(), size, renderer.read_pixels(size));
}

int ScriptedRun::exit_status() const {
  if (!player_ || player_->exit_status() == app::kExitOk) {
    return app::kExitOk;
  }
  std::cerr << "foldlab: --play: " << detail::escaped_lines(player_->failure())
            << "\n";  // gui and render alike
  return player_->exit_status();
}

void FrameTimes::start() {
  start_ = std::chrono::steady_clock::now();
}

void FrameTimes::stop(Surface& surface) {
  if (!enabled_) {
    return;
  }
  surface.finish();
  frame_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count());
}

void FrameTimes::print_report(const char* backend, const std::string& animate_key,
                              Explorer& explorer, const KeyLatency& latency) const {
  if (!enabled_ || frame_ms_.empty()) {
    return;
  }
  std::vector<double> sorted = frame_ms_;
  std::sort(sorted.begin(), sorted.end());
  const double mean =
      std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(sorted.size());
  const double p95 = sorted[std::min(
      sorted.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size())))];
  nlohmann::json report = {
      {"backend", backend},
      {"frames", sorted.size()},
      {"mean_ms", mean},
      {"p95_ms", p95},
      {"max_ms", sorted.back()},
      {"animate", animate_key},
      {"notices", explorer.notices()},
      {"latency", latency.report()},
  };
  report.update(explorer_state_json(explorer));
  std::cout << report.dump(2) << "\n";
}

void write_requested_picture(Explorer& explorer, Renderer& renderer, FrameSize size) {
  if (const std::optional<PictureRequest> request = explorer.take_screenshot_request()) {
    try {
      if (request->spec) {
        explorer.write_picture(request->path, *request->spec);
        explorer.notify("Wrote " + std::filesystem::absolute(request->path).string(), false);
        return;
      }
      std::vector<std::uint8_t> pixels = renderer.read_pixels(size);
      FrameSize shown = size;
      if (request->crop) {
        // Display pixels to the framebuffer's, which a high-DPI screen makes larger.
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        const float sx = display.x > 0.0f ? static_cast<float>(size.width) / display.x : 1.0f;
        const float sy = display.y > 0.0f ? static_cast<float>(size.height) / display.y : 1.0f;
        const PanelRect& r = *request->crop;
        shown = crop_pixels(pixels, size, static_cast<int>(std::lround(r.pos.x * sx)),
                            static_cast<int>(std::lround(r.pos.y * sy)),
                            static_cast<int>(std::lround(r.size.x * sx)),
                            static_cast<int>(std::lround(r.size.y * sy)));
      }
      write_png(request->path.c_str(), shown, pixels);
      explorer.notify("Wrote " + std::filesystem::absolute(request->path).string(), false);
    } catch (const SurfaceError& e) {
      explorer.notify(std::string("Not exported: ") + e.what(), true);
    }
  }
}

}  // namespace foldlab::gui
