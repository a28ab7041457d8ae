// The pieces a scripted run adds around the frame loop: how many frames, an input moved every
// frame as a dragged slider would move it, frame times and the JSON report, and screenshots.
// None of them draws; the frame loop calls them at fixed points.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/common/inputs.hpp"
#include "app/gui/animated_input.hpp"
#include "app/gui/explorer.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/key_latency.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/surface.hpp"

namespace foldlab::gui {

// How many frames to run, what a scripted frame does before ImGui::NewFrame, and the pictures it
// takes after the frame is drawn: the two points where it plugs into the frame loop.
class ScriptedRun {
 public:
  // frames == 0: until the window is closed, with the user's input, or until `player` has played
  // its script. `final_screenshot`: a PNG of the last frame (none when empty). `input_files`: what
  // the run read, which a screenshot step must not overwrite.
  ScriptedRun(int frames, std::optional<AnimatedInput> animation,
              std::optional<InputPlayer> player = std::nullopt, std::string final_screenshot = {},
              std::vector<app::NamedPath> input_files = {});
  // True while another frame should run. A scripted run waits (up to 30 s) for background work
  // before its last frame, so that the picture shows a finished regime map.
  bool wants_frame(int frame, const Explorer& explorer);
  bool is_last(int frame) const { return frames_ > 0 && frame + 1 == frames_ + extra_frames_; }
  // Only a window in the user's hands may sleep between frames: a script wants every frame.
  bool may_wait_for_input() const { return frames_ == 0 && !animation_ && !player_; }
  // After the surface polled its input: the played input replaces it, and the surface follows a
  // resize step; scripted frames take no pointer input otherwise, so that a stray cursor cannot
  // change the picture; the animated input moves. False when the script is over (or failed):
  // this frame does not run.
  bool before_frame(Explorer& explorer, Surface& surface, int frame);
  // After the frame is drawn, before it is presented: the screenshots asked for (a screenshot
  // step's, the last frame's).
  void after_render(Explorer& explorer, Renderer& renderer, FrameSize size, int frame);
  // kExitOk, or 1 with the failed step on stderr.
  int exit_status() const;

 private:
  int frames_;
  int extra_frames_ = 0;
  std::optional<AnimatedInput> animation_;
  std::optional<InputPlayer> player_;
  std::string final_screenshot_;
  std::vector<app::NamedPath> input_files_;
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
  // With `latency`: how long keys took to show (key_latency.hpp).
  void print_report(const char* backend, const std::string& animate_key, Explorer& explorer,
                    const KeyLatency& latency) const;

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::vector<double> frame_ms_;
};

// Writes the PNG the Export panel asked for, from the frame just drawn (before it is presented).
void write_requested_picture(Explorer& explorer, Renderer& renderer, FrameSize size);

}  // namespace foldlab::gui
