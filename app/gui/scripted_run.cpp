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
namespace {

// A point of [lo, hi] at fraction f, evenly on the input's scale.
double along(double lo, double hi, bool logarithmic, double f) {
  return logarithmic ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f;
}

}  // namespace

AnimatedInput::AnimatedInput(const std::string& key, const Parameters& base) : key_(key) {
  const std::vector<std::string>& keys = sweepable_keys();
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
    throw app::InputError("--animate " + key + ": not one of " + detail::join_comma(keys));
  }
  const InputSpec& spec = *find_input(key);
  logarithmic_ = spec.scale == InputScale::logarithmic;
  // d must stay below L/2, for one: keep to the values the model accepts with the rest as is.
  constexpr int kProbes = 200;
  std::optional<double> first;
  double last = 0.0;
  for (int i = 0; i <= kProbes; ++i) {
    const double v =
        along(spec.typical_lo, spec.typical_hi, logarithmic_, static_cast<double>(i) / kProbes);
    Parameters p = base;
    if (!set_input(p, key, v) && validate(p).empty()) {
      first = first.value_or(v);
      last = v;
    }
  }
  if (!first) {
    throw app::InputError("--animate " + key +
                          ": no value of its slider is valid with the other inputs");
  }
  lo_ = *first;
  hi_ = last;
}

double AnimatedInput::value(int frame) const {
  const double phase = std::abs(std::fmod(frame / 60.0, 2.0) - 1.0);  // 1 -> 0 -> 1
  return along(lo_, hi_, logarithmic_, 1.0 - phase);
}

ScriptedRun::ScriptedRun(int frames, std::optional<AnimatedInput> animation,
                         std::optional<InputPlayer> player)
    : frames_(frames),
      animation_(std::move(animation)),
      player_(std::move(player)),
      deadline_(std::chrono::steady_clock::now() + std::chrono::seconds(30)) {}

bool ScriptedRun::wants_frame(int frame, const Explorer& explorer) {
  if (frames_ == 0) {
    return true;
  }
  if (frame + 1 == frames_ + extra_frames_ && explorer.busy() &&
      std::chrono::steady_clock::now() < deadline_) {
    ++extra_frames_;
  }
  return frame < frames_ + extra_frames_;
}

void ScriptedRun::before_new_frame(Explorer& explorer, int frame) const {
  if (frames_ > 0) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
  }
  if (animation_) {
    explorer.set_input(animation_->key(), animation_->value(frame));
  }
}

bool ScriptedRun::play(Explorer& explorer, Surface& surface) {
  if (!player_) {
    return true;
  }
  if (!player_->before_new_frame(ImGui::GetIO(), explorer)) {
    return false;
  }
  if (const std::optional<std::pair<int, int>> size = player_->take_resize_request()) {
    surface.resize(FrameSize{size->first, size->second});
  }
  return true;
}

std::optional<std::string> ScriptedRun::take_play_screenshot() {
  return player_ ? player_->take_screenshot_request() : std::nullopt;
}

int ScriptedRun::exit_status() const {
  if (!player_ || player_->exit_status() == app::kExitOk) {
    return app::kExitOk;
  }
  std::cerr << "foldlab: --play: " << player_->failure() << "\n";  // gui and render alike
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
                              Explorer& explorer) const {
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
  };
  report.update(explorer_state_json(explorer));
  std::cout << report.dump(2) << "\n";
}

void take_screenshots(Explorer& explorer, Renderer& renderer, FrameSize size,
                      const std::string& final_path, bool last_frame) {
  if (const std::optional<std::string> path = explorer.take_screenshot_request()) {
    try {
      write_png(path->c_str(), size, renderer.read_pixels(size));
      explorer.notify("Wrote " + std::filesystem::absolute(*path).string(), false);
    } catch (const SurfaceError& e) {
      explorer.notify(std::string("Not exported: ") + e.what(), true);
    }
  }
  if (last_frame && !final_path.empty()) {
    write_png(final_path.c_str(), size, renderer.read_pixels(size));
  }
}

}  // namespace foldlab::gui
