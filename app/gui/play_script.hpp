// The `--play` script format (docs/cli.md): its key chords and window sizes, and the check of a
// whole script before any frame runs. Apart from the input player, so that the check runs (and is
// fuzzed) with no window, no ImGui context and no explorer.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace foldlab::gui {

// Key names of chords, as GLFW numbers them (the window's backend indexes io.KeysDown so; the
// headless surface is given the same map). `imgui` is the named key ImGui itself reads, if any.
struct KeyName {
  const char* name;
  int glfw;
  int imgui;
};
std::span<const KeyName> named_keys();
inline constexpr int kLeftShift = 340;
inline constexpr int kLeftCtrl = 341;
inline constexpr int kLeftAlt = 342;

struct Chord {
  bool ctrl = false;
  bool shift = false;
  bool alt = false;
  int glfw = -1;
  int imgui = -1;
};

// "ctrl+shift+z", "escape", "plus": nullopt when it is not a chord.
std::optional<Chord> parse_chord(std::string text);

// A kind of step: named by its action field ({"drag": "w", "dx": 40}), with the other fields it may
// have and the check of its values.
struct StepKind {
  enum class Id {
    drag,
    click,
    click_photo,
    key,
    type,
    resize,
    frames,
    screenshot,
    expect,
    visible,
    absent,
    hover_sweep
  };
  Id id;
  std::string_view name;
  std::span<const std::string_view> options;
  void (*check)(const nlohmann::json& step, std::vector<std::string>& problems);
};
// The kind of a step that play_script_problems found runnable.
const StepKind& step_kind(const nlohmann::json& step);

// A drag step's key for a tile's edge, "edge:" and the edge's key ("edge:layout_fold_plot"): the
// grip a coarse pointer has on it (Layout::tile_handles).
inline constexpr std::string_view kTileEdgePrefix = "edge:";

// The frames all of a script's steps may add up to.
inline constexpr long long kMaxScriptFrames = 100000;
// The mouse moves of a drag between its press and its release.
inline constexpr int kDragMoves = 6;

// The frames a runnable step takes as the input player plays it: a press is four (hover, down,
// up, up) and a drag's moves come between; a key chord four; a typed text one a character and
// one more; a check (expect, visible, absent) or a screenshot one.
long long step_frames(const nlohmann::json& step);

// Every problem of a script, each "step N: ..." or about the whole; empty when it can run. Text
// from the script is echoed through detail::cut.
std::vector<std::string> play_script_problems(const nlohmann::json& script);

}  // namespace foldlab::gui
