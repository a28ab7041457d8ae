// Input playback (`gui --play SCRIPT.json`): a script's steps become the mouse, keys and text that
// ImGui reads each frame, so that a run goes through the real widgets as a person's hands would,
// and its `expect` steps check the report's fields between them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/gui/explorer.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/play_script.hpp"

namespace foldlab::gui {

// What the explorer shows now, as `--report` prints it without frame times: the solution, the
// pipeline counters, the sliders' values and the document's state.
nlohmann::json explorer_state_json(Explorer& explorer);

class InputPlayer {
 public:
  // Reads and checks the whole script first. Throws app::InputError naming every problem.
  explicit InputPlayer(const std::filesystem::path& script_path);
  InputPlayer(const nlohmann::json& script, const std::string& name);

  // Before ImGui::NewFrame, after the platform polled: sets this frame's mouse, keys and text,
  // starting the next steps as needed (an `expect` is checked when it is reached). Returns false
  // once the script is over or a step failed: no further frame should run.
  bool before_new_frame(ImGuiIO& io, Explorer& explorer);
  // A PNG to write from the frame just drawn, if a `screenshot` step asked for one.
  std::optional<std::string> take_screenshot_request();
  // A size to switch to before the next frame, if a `resize` step asked for one.
  std::optional<FrameSize> take_resize_request();
  // Empty while every step held; else which step failed and how.
  const std::string& failure() const { return failure_; }
  // The exit status: kExitOk, or 1 when a step failed.
  int exit_status() const;

  // One frame of input.
  struct FrameInput {
    ImVec2 mouse{-1.0f, -1.0f};
    bool mouse_down = false;
    bool ctrl = false;
    bool shift = false;
    bool alt = false;
    int key = -1;  // index into io.KeysDown
    std::string text;
    std::string screenshot;
    std::optional<FrameSize> resize;
    bool until_idle = false;  // a wait that ends once no panel is busy (a field solved)
  };

 private:
  void parse(const nlohmann::json& script);
  // Turns step `index` into frames of input, or fails it; false when it failed.
  bool start_step(std::size_t index, ImGuiIO& io, Explorer& explorer);
  void fail(std::size_t index, const std::string& why);
  // The frames of a press at `from`, moved to `to` in `moves` frames, and released.
  void queue_press(ImVec2 from, ImVec2 to, int moves);
  void queue_key(const Chord& chord, const ImGuiIO& io);
  void queue_text(const std::string& text);
  // A new frame size (nullopt: none), then frames at it.
  void queue_resize(std::optional<FrameSize> size);
  void queue_idle(std::size_t frames, bool until_idle = false);
  void queue_screenshot(const std::string& png_path);
  // Each fails the step (and returns null or false) when what it needs is not on screen.
  std::optional<SliderPlace> find_slider(std::size_t index, const std::string& key,
                                         Explorer& explorer);
  bool reachable(std::size_t index, const std::string& key, const SliderPlace& place, ImVec2 at);
  bool click_slider(std::size_t index, const nlohmann::json& step, Explorer& explorer);
  bool click_label(std::size_t index, const std::string& label, const std::string& panel_key);
  bool drag_slider(std::size_t index, const nlohmann::json& step, Explorer& explorer);
  // A tile's edge dragged by its grip, "dx" and "dy" pixels.
  bool drag_tile_edge(std::size_t index, const nlohmann::json& step, Explorer& explorer);
  bool click_photo(std::size_t index, const nlohmann::json& step, Explorer& explorer);
  bool hover_sweep(std::size_t index, const nlohmann::json& step, Explorer& explorer);
  bool check_expect(std::size_t index, const nlohmann::json& expect, Explorer& explorer);
  // A `visible` or `absent` step.
  bool check_drawn(std::size_t index, const nlohmann::json& step);

  std::vector<nlohmann::json> steps_;
  std::size_t next_step_ = 0;
  std::vector<FrameInput> queue_;  // the frames of the current step, front first
  std::size_t queue_at_ = 0;
  ImVec2 mouse_{-1.0f, -1.0f};
  std::optional<std::string> screenshot_;
  std::optional<FrameSize> resize_;
  std::string failure_;
};

}  // namespace foldlab::gui
