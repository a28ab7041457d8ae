// How long a key takes to show: from the moment the window hands a key press to the explorer (the
// GLFW key callback) to the end of the frame that first shows what it changed (an arrow key on a
// focused slider: the slider's value, the plots and the 3D view), and where that time goes.
// `gui --report` gives it as `latency` (docs/performance.md).
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace foldlab {
class Scene;
}

namespace foldlab::gui {

class KeyLatency {
 public:
  using Clock = std::chrono::steady_clock;

  // The parts of a key's time, in the order they happen. `wait`: from the callback to the start
  // of the frame that takes the key (the frame being drawn when it came, or a key queued behind
  // another); `input`: polling and the platform's new frame; `ui`: the panels' widgets and
  // layout, less what is counted apart; `solve`: the model; `mesh`: fold lines, grid and normals;
  // `cloth`: the 3D view's uploads and draw calls; `draw`: ImGui's draw data to the GL; `swap`:
  // presenting the frame and waiting for the GPU to finish it.
  enum Part { wait, input, ui, solve, mesh, cloth, draw, swap, kPartCount };
  static constexpr std::array<const char*, kPartCount> kPartNames = {
      "wait_ms", "input_ms", "ui_ms", "solve_ms", "mesh_ms", "cloth_ms", "draw_ms", "swap_ms"};

  // One key's time and its parts, ms.
  struct Record {
    double key_to_frame_ms = 0.0;
    std::array<double, kPartCount> parts_ms{};
    bool cloth_redrawn = false;  // the 3D view drew a new picture in that frame
  };

  // The frame's steps, in order: its start (before polling); the input read, with the callback
  // times of the key presses this frame takes; the panels built (the scene's stage times and the
  // 3D view's render time so far); ImGui's draw data drawn; the frame presented and finished.
  void frame_started(Clock::time_point now);
  // `cloth_render_ms_total`: the renderer's time in the 3D view's uploads and draw calls so far.
  // A key counts as shown at the end of the first frame after it that solved the model again.
  void input_read(Clock::time_point now, std::span<const Clock::time_point> keys_taken,
                  const Scene& scene, double cloth_render_ms_total);
  void built(Clock::time_point now, const Scene& scene, double cloth_render_ms_total);
  void drawn(Clock::time_point now);
  void finished(Clock::time_point now, const Scene& scene);

  const std::vector<Record>& records() const { return records_; }
  // `latency` for the report: the count, median and 90th percentile of the whole and of each
  // part, and the last few keys in full; null when no key changed anything.
  nlohmann::json report() const;

  // A key not shown within this many frames of being taken changed nothing that shows (a key
  // with no focused slider, a slider already at its end): it is not counted.
  static constexpr int kFramesToShow = 3;

 private:
  struct Pending {
    Clock::time_point key;
    std::uint64_t solution_version = 0;
    int frames = 0;
    Record record;  // the parts so far
  };
  Clock::time_point frame_start_{};
  Clock::time_point last_finished_{};
  Clock::time_point input_read_{};
  Clock::time_point built_{};
  Clock::time_point drawn_{};
  double solve_ms_ = 0.0;  // this frame's
  double mesh_ms_ = 0.0;
  double cloth_ms_ = 0.0;
  double solve_total_ms_ = 0.0;  // the totals when the input was read
  double mesh_total_ms_ = 0.0;
  double cloth_total_ms_ = 0.0;
  std::vector<Pending> pending_;
  std::vector<Record> records_;
};

}  // namespace foldlab::gui
