// The pieces a scripted run adds around the frame loop: how many frames, an input moved every
// frame as a dragged slider would move it, frame times and the JSON report, and screenshots.
// None of them draws; the frame loop calls them at fixed points.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/animated_input.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/surface.hpp"

namespace foldlab::gui {

// How many frames to run, and what a scripted frame does before ImGui::NewFrame.
class ScriptedRun {
 public:
  // frames == 0: until the window is closed, with the user's input, or until `player` has played
  // its script.
  ScriptedRun(int frames, std::optional<AnimatedInput> animation,
              std::optional<InputPlayer> player = std::nullopt);
  // True while another frame should run. A scripted run waits (up to 30 s) for background work
  // before its last frame, so that the picture shows a finished regime map.
  bool wants_frame(int frame, const Explorer& explorer);
  bool is_last(int frame) const { return frames_ > 0 && frame + 1 == frames_ + extra_frames_; }
  // Only a window in the user's hands may sleep between frames: a script wants every frame.
  bool may_wait_for_input() const { return frames_ == 0 && !animation_ && !player_; }
  // After the surface polled its input: scripted frames take no pointer input, so that a stray
  // cursor cannot change the picture; the animated input moves.
  void before_new_frame(Explorer& explorer, int frame) const;
  // After the surface polled its input: the played input replaces it, and the surface follows a
  // resize step. False when the script is over (or failed): this frame does not run.
  bool play(Explorer& explorer, Surface& surface);
  // A screenshot step's PNG, to write from the frame just drawn.
  std::optional<std::string> take_play_screenshot();
  // kExitOk, or 1 with the failed step on stderr.
  int exit_status() const;

 private:
  int frames_;
  int extra_frames_ = 0;
  std::optional<AnimatedInput> animation_;
  std::optional<InputPlayer> player_;
  std::chrono::steady_clock::time_point deadline_;
};

// Frame times for `--report`, and the report itself.
class FrameTimes {
 public:
  explicit FrameTimes(bool enabled) : enabled_(enabled) {}
  void start();
  // After present: waits for the GPU so that the time covers the whole frame.
  void stop(Surface& surface);
  // Prints the JSON report (frame times, pipeline counters, the solution) on stdout.
  void print_report(const char* backend, const std::string& animate_key, Explorer& explorer) const;

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::vector<double> frame_ms_;
};

// Writes the PNGs asked for, from the frame just drawn (before it is presented): the Export
// panel's request, and `final_path` on the last frame of a scripted run.
void take_screenshots(Explorer& explorer, Renderer& renderer, FrameSize size,
                      const std::string& final_path, bool last_frame);

}  // namespace foldlab::gui
