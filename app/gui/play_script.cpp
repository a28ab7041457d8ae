#include "app/gui/play_script.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <imgui.h>

#include "app/gui/surface.hpp"
#include "app/gui/tiles.hpp"
#include "core/analysis/sweep.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

using nlohmann::json;

const KeyName kNamedKeys[] = {
    {"escape", 256, ImGuiKey_Escape},
    {"enter", 257, ImGuiKey_Enter},
    {"tab", 258, ImGuiKey_Tab},
    {"backspace", 259, ImGuiKey_Backspace},
    {"insert", 260, ImGuiKey_Insert},
    {"delete", 261, ImGuiKey_Delete},
    {"right", 262, ImGuiKey_RightArrow},
    {"left", 263, ImGuiKey_LeftArrow},
    {"down", 264, ImGuiKey_DownArrow},
    {"up", 265, ImGuiKey_UpArrow},
    {"pageup", 266, ImGuiKey_PageUp},
    {"pagedown", 267, ImGuiKey_PageDown},
    {"home", 268, ImGuiKey_Home},
    {"end", 269, ImGuiKey_End},
    {"space", 32, ImGuiKey_Space},
    {"minus", 45, -1},
    {"equal", 61, -1},
    {"plus", 61, -1},
    {"kp_add", 334, -1},
    {"kp_subtract", 333, -1},
};
}  // namespace

std::span<const KeyName> named_keys() {
  return kNamedKeys;
}

std::optional<Chord> parse_chord(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Chord chord;
  std::string_view rest = text;
  for (;;) {
    const std::size_t plus = rest.find('+', 1);
    if (plus == std::string_view::npos) {
      break;
    }
    const std::string_view mod = rest.substr(0, plus);
    if (mod == "ctrl") {
      chord.ctrl = true;
    } else if (mod == "shift") {
      chord.shift = true;
    } else if (mod == "alt") {
      chord.alt = true;
    } else {
      return std::nullopt;
    }
    rest.remove_prefix(plus + 1);
  }
  if (rest.size() == 1 && std::isalnum(static_cast<unsigned char>(rest[0]))) {
    chord.glfw = std::toupper(static_cast<unsigned char>(rest[0]));
    return chord;
  }
  if (rest == "+") {
    rest = "plus";
  } else if (rest == "-") {
    rest = "minus";
  } else if (rest == "=") {
    rest = "equal";
  }
  for (const KeyName& key : kNamedKeys) {
    if (rest == key.name) {
      chord.glfw = key.glfw;
      chord.imgui = key.imgui;
      return chord;
    }
  }
  return std::nullopt;
}

namespace {

bool is_slider_key(const json& value) {
  const std::vector<std::string>& keys = sweepable_keys();
  return value.is_string() &&
         std::find(keys.begin(), keys.end(), value.get<std::string>()) != keys.end();
}

bool is_tile_edge_key(const json& value) {
  if (!value.is_string()) {
    return false;
  }
  const std::string text = value.get<std::string>();
  if (!text.starts_with(kTileEdgePrefix)) {
    return false;
  }
  for (int split = 0; split < kSplitCount; ++split) {
    if (text.substr(kTileEdgePrefix.size()) == kSplits[split].key) {
      return true;
    }
  }
  return false;
}

using Problems = std::vector<std::string>;

void check_drag(const json& step, Problems& problems) {
  const auto pixels = [&step](const char* field) {
    return step.contains(field) && step[field].is_number() &&
           std::abs(step[field].get<double>()) <= 10000.0;
  };
  if (is_tile_edge_key(step["drag"])) {
    if ((step.contains("dx") && !pixels("dx")) || (step.contains("dy") && !pixels("dy")) ||
        (!step.contains("dx") && !step.contains("dy"))) {
      problems.push_back("an edge's drag needs \"dx\" or \"dy\" (or both): numbers of pixels");
    }
    if (step.contains("shift")) {
      problems.push_back("\"shift\" belongs to a slider's drag");
    }
    return;
  }
  if (!is_slider_key(step["drag"])) {
    std::vector<std::string> edges;
    for (int split = 0; split < kSplitCount; ++split) {
      edges.push_back(std::string(kTileEdgePrefix) + kSplits[split].key);
    }
    problems.push_back("drag needs a slider key (" + detail::join_comma(sweepable_keys()) +
                       ") or a tile's edge (" + detail::join_comma(edges) + "), not " +
                       detail::cut(step["drag"].dump()));
  }
  if (!pixels("dx")) {
    problems.push_back("drag needs \"dx\": a number of pixels");
  }
  if (step.contains("dy")) {
    problems.push_back("\"dy\" belongs to a tile edge's drag");
  }
  if (step.contains("shift") && !step["shift"].is_boolean()) {
    problems.push_back("\"shift\" must be true or false, not " + detail::cut(step["shift"].dump()));
  }
}

// "in": where a label is looked for, a panel's key or the menu bar.
void check_panel_key(const json& step, Problems& problems) {
  if (step.contains("in") && (!step["in"].is_string() || step["in"].get<std::string>().empty())) {
    problems.push_back("\"in\" needs a panel's key (results, parameters, ...) or menu_bar, not " +
                       detail::cut(step["in"].dump()));
  }
}

void check_click(const json& step, Problems& problems) {
  const json& arg = step["click"];
  if (!step.contains("at")) {
    if (!arg.is_string() || arg.get<std::string>().empty()) {
      problems.push_back("click needs a label or a slider key with \"at\", not " +
                         detail::cut(arg.dump()));
    }
    if (step.contains("ctrl")) {
      problems.push_back("\"ctrl\" belongs to a click on a slider (with \"at\")");
    }
    check_panel_key(step, problems);
    return;
  }
  if (step.contains("in")) {
    problems.push_back("\"in\" belongs to a click on a label (without \"at\")");
  }
  if (!is_slider_key(arg)) {
    problems.push_back("click with \"at\" needs a slider key (" +
                       detail::join_comma(sweepable_keys()) + "), not " + detail::cut(arg.dump()));
  }
  if (step.contains("ctrl") && !step["ctrl"].is_boolean()) {
    problems.push_back("\"ctrl\" must be true or false, not " + detail::cut(step["ctrl"].dump()));
  }
  if (!step["at"].is_number() || step["at"].get<double>() < 0.0 || step["at"].get<double>() > 1.0) {
    problems.push_back("\"at\" must be a fraction from 0 to 1, not " +
                       detail::cut(step["at"].dump()));
  }
}

void check_click_photo(const json& step, Problems& problems) {
  const json& arg = step["click_photo"];
  if (!arg.is_array() || arg.size() != 2 || !arg[0].is_number() || !arg[1].is_number() ||
      !(arg[0].get<double>() >= 0.0) || !(arg[1].get<double>() >= 0.0)) {
    problems.push_back("click_photo needs [X, Y]: a pixel of the loaded photo, not " +
                       detail::cut(arg.dump()));
  }
}

void check_key(const json& step, Problems& problems) {
  const json& arg = step["key"];
  if (!arg.is_string() || !parse_chord(arg.get<std::string>())) {
    problems.push_back("key " + detail::cut(arg.dump()) +
                       " is not a chord such as \"ctrl+z\", \"ctrl+shift+z\", \"escape\"");
  }
}

// "visible" or "absent": the text a person reads, anywhere or in one panel ("in").
void check_seen(const json& step, Problems& problems) {
  const std::string action = step.contains("visible") ? "visible" : "absent";
  const json& arg = step[action];
  if (!arg.is_string() || arg.get<std::string>().empty()) {
    problems.push_back(action + " needs the text to look for, not " + detail::cut(arg.dump()));
  }
  check_panel_key(step, problems);
}

void check_type(const json& step, Problems& problems) {
  if (!step["type"].is_string()) {
    problems.push_back("type needs a string, not " + detail::cut(step["type"].dump()));
  }
}

void check_resize(const json& step, Problems& problems) {
  const json& arg = step["resize"];
  if (!arg.is_string() || !parse_frame_size(arg.get<std::string>())) {
    problems.push_back("resize needs " + frame_size_rule() + ", not " + detail::cut(arg.dump()));
  }
}

void check_frames(const json& step, Problems& problems) {
  if (step.contains("until_idle") && !step["until_idle"].is_boolean()) {
    problems.push_back("until_idle is true or false, not " +
                       detail::cut(step["until_idle"].dump()));
  }
  const json& arg = step["frames"];
  if (!arg.is_number_integer() || arg.get<long long>() < 1 || arg.get<long long>() > 100000) {
    problems.push_back("frames needs a whole number from 1 to 100000, not " +
                       detail::cut(arg.dump()));
  }
}

void check_screenshot(const json& step, Problems& problems) {
  const json& arg = step["screenshot"];
  if (!arg.is_string() || !arg.get<std::string>().ends_with(".png")) {
    problems.push_back("screenshot needs a file name ending in .png, not " +
                       detail::cut(arg.dump()));
  }
}

void check_expect(const json& step, Problems& problems) {
  const json& arg = step["expect"];
  if (!arg.is_object() || arg.empty()) {
    problems.push_back("expect needs an object of FIELD.PATH: VALUE, [LO, HI] or [] (empty)");
    return;
  }
  for (const auto& [path, wanted] : arg.items()) {
    const bool range = wanted.is_array() && wanted.size() == 2 && wanted[0].is_number() &&
                       wanted[1].is_number() && wanted[0].get<double>() <= wanted[1].get<double>();
    if (wanted.is_array() ? !range && !wanted.empty() : wanted.is_object()) {
      problems.push_back("expect " + detail::cut(path) + ": " + detail::cut(wanted.dump()) +
                         " is neither a value nor [LO, HI] with LO <= HI");
    }
  }
}

// "hover_sweep": the mouse held on a Sweep plot's sample nearest "x" (the unit the axis shows).
void check_hover_sweep(const json& step, Problems& problems) {
  const json& arg = step["hover_sweep"];
  if (!arg.is_string() || (arg != "n" && arg != "Q" && arg != "z_max")) {
    problems.push_back("hover_sweep needs the plot: \"n\", \"Q\" or \"z_max\", not " +
                       detail::cut(arg.dump()));
  }
  if (!step.contains("x") || !step["x"].is_number()) {
    problems.push_back("hover_sweep needs \"x\": a value of the swept input, in the axis's unit");
  }
}

constexpr std::string_view kDragOptions[] = {"dx", "dy", "shift"};
constexpr std::string_view kHoverSweepOptions[] = {"x"};
constexpr std::string_view kSeenOptions[] = {"in"};
constexpr std::string_view kClickOptions[] = {"at", "ctrl", "in"};
constexpr std::string_view kFramesOptions[] = {"until_idle"};

// Every kind of step: its action (the field that names it), the other fields it may have, and the
// check of its values. The player turns each kind into input (InputPlayer::start_step).
const StepKind kStepKinds[] = {
    {StepKind::Id::drag, "drag", kDragOptions, check_drag},
    {StepKind::Id::click, "click", kClickOptions, check_click},
    {StepKind::Id::click_photo, "click_photo", {}, check_click_photo},
    {StepKind::Id::key, "key", {}, check_key},
    {StepKind::Id::type, "type", {}, check_type},
    {StepKind::Id::resize, "resize", {}, check_resize},
    {StepKind::Id::frames, "frames", kFramesOptions, check_frames},
    {StepKind::Id::screenshot, "screenshot", {}, check_screenshot},
    {StepKind::Id::expect, "expect", {}, check_expect},
    {StepKind::Id::visible, "visible", kSeenOptions, check_seen},
    {StepKind::Id::absent, "absent", kSeenOptions, check_seen},
    {StepKind::Id::hover_sweep, "hover_sweep", kHoverSweepOptions, check_hover_sweep},
};

// The problems of one step; empty when it can run.
Problems step_problems(const json& step) {
  if (!step.is_object() || step.empty()) {
    return {"is not an object with one action"};
  }
  std::vector<std::string> actions;
  const StepKind* kind = nullptr;
  for (const StepKind& candidate : kStepKinds) {
    if (step.contains(candidate.name)) {
      actions.emplace_back(candidate.name);
      kind = &candidate;
    }
  }
  if (actions.size() != 1) {
    if (!actions.empty()) {
      return {"has more than one action: " + detail::join_comma(actions)};
    }
    std::vector<std::string> names;
    for (const StepKind& candidate : kStepKinds) {
      names.emplace_back(candidate.name);
    }
    return {"has no action (" + detail::join_comma(names) + ")"};
  }
  Problems problems;
  for (const auto& [name, value] : step.items()) {
    if (name != kind->name &&
        std::find(kind->options.begin(), kind->options.end(), name) == kind->options.end()) {
      problems.push_back("\"" + detail::cut(name) + "\" does not belong to a " +
                         std::string(kind->name) + " step");
    }
  }
  kind->check(step, problems);
  return problems;
}

}  // namespace

long long step_frames(const json& step) {
  switch (step_kind(step).id) {
    case StepKind::Id::drag:
      return 4 + kDragMoves;
    case StepKind::Id::click:
    case StepKind::Id::click_photo:
    case StepKind::Id::key:
    case StepKind::Id::resize:
      return 4;
    case StepKind::Id::type: {
      // One frame a UTF-8 character, and one that ends the typing.
      const std::string text = step["type"].get<std::string>();
      return 1 + std::count_if(text.begin(), text.end(), [](char c) {
               return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
             });
    }
    case StepKind::Id::frames:
      return step["frames"].get<long long>();
    case StepKind::Id::hover_sweep:
      return 3;
    case StepKind::Id::screenshot:
    case StepKind::Id::expect:
    case StepKind::Id::visible:
    case StepKind::Id::absent:
      return 1;
  }
  return 1;
}

const StepKind& step_kind(const json& step) {
  for (const StepKind& kind : kStepKinds) {
    if (step.contains(kind.name)) {
      return kind;
    }
  }
  throw std::invalid_argument("not a checked step: " + detail::cut(step.dump()));
}

std::vector<std::string> play_script_problems(const json& script) {
  if (!script.is_object() || !script.contains("steps") || !script.at("steps").is_array()) {
    return {"needs {\"steps\": [...]}"};
  }
  std::vector<std::string> problems;
  for (const auto& [name, value] : script.items()) {
    if (name != "steps") {
      problems.push_back("\"" + detail::cut(name) +
                         "\" is not a field of a script (only \"steps\")");
    }
  }
  const json& steps = script.at("steps");
  // Each step is bounded, and so is their sum: 1000 frames of the software renderer take about
  // 20 s, so a script runs for at most about half an hour. Every step counts, not only frames
  // steps: a long enough type step is as many frames.
  long long frames = 0;
  std::optional<std::size_t> past_cap;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::vector<std::string> step = step_problems(steps[i]);
    for (const std::string& problem : step) {
      problems.push_back("step " + std::to_string(i + 1) + ": " + problem);
    }
    if (step.empty()) {
      frames += step_frames(steps[i]);
      if (frames > kMaxScriptFrames && !past_cap) {
        past_cap = i;
      }
    }
  }
  if (past_cap) {
    problems.push_back("step " + std::to_string(*past_cap + 1) + " (" +
                       std::string(step_kind(steps[*past_cap]).name) +
                       ") takes the script past the cap: its steps add up to " +
                       std::to_string(frames) + ", more than the " +
                       std::to_string(kMaxScriptFrames) + " frames a script may run");
  }
  return problems;
}

}  // namespace foldlab::gui
