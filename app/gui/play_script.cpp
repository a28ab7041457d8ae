#include "app/gui/play_script.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

#include <imgui.h>

#include "app/gui/surface.hpp"
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

// The problems of one step; empty when it can run.
std::vector<std::string> step_problems(const json& step) {
  if (!step.is_object() || step.empty()) {
    return {"is not an object with one action"};
  }
  static const char* const kActions[] = {"drag",   "click",   "click_photo", "key",
                                         "type",   "resize",  "frames",      "screenshot",
                                         "expect", "visible", "absent"};
  std::vector<std::string> actions;
  for (const char* action : kActions) {
    if (step.contains(action)) {
      actions.emplace_back(action);
    }
  }
  if (actions.size() != 1) {
    return {actions.empty() ? "has no action (drag, click, click_photo, key, type, resize, "
                              "frames, screenshot, expect, visible or absent)"
                            : "has more than one action: " + detail::join_comma(actions)};
  }
  const std::string& action = actions.front();
  std::vector<std::string> problems;
  for (const auto& [name, value] : step.items()) {
    const bool allowed = name == action ||
                         (action == "drag" && (name == "dx" || name == "shift")) ||
                         (action == "click" && (name == "at" || name == "ctrl")) ||
                         ((action == "visible" || action == "absent") && name == "in");
    if (!allowed) {
      problems.push_back("\"" + detail::cut(name) + "\" does not belong to a " + action + " step");
    }
  }
  const json& arg = step.at(action);
  const std::string keys = detail::join_comma(sweepable_keys());
  if (action == "drag") {
    if (!is_slider_key(arg)) {
      problems.push_back("drag needs a slider key (" + keys + "), not " + detail::cut(arg.dump()));
    }
    if (!step.contains("dx") || !step["dx"].is_number() ||
        std::abs(step["dx"].get<double>()) > 10000.0) {
      problems.push_back("drag needs \"dx\": a number of pixels");
    }
    if (step.contains("shift") && !step["shift"].is_boolean()) {
      problems.push_back("\"shift\" must be true or false, not " +
                         detail::cut(step["shift"].dump()));
    }
  } else if (action == "click") {
    if (step.contains("at")) {
      if (!is_slider_key(arg)) {
        problems.push_back("click with \"at\" needs a slider key (" + keys + "), not " +
                           detail::cut(arg.dump()));
      }
      if (step.contains("ctrl") && !step["ctrl"].is_boolean()) {
        problems.push_back("\"ctrl\" must be true or false, not " +
                           detail::cut(step["ctrl"].dump()));
      }
      if (!step["at"].is_number() || step["at"].get<double>() < 0.0 ||
          step["at"].get<double>() > 1.0) {
        problems.push_back("\"at\" must be a fraction from 0 to 1, not " +
                           detail::cut(step["at"].dump()));
      }
    } else if (!arg.is_string() || arg.get<std::string>().empty()) {
      problems.push_back("click needs a label or a slider key with \"at\", not " +
                         detail::cut(arg.dump()));
    }
  } else if (action == "click_photo") {
    if (!arg.is_array() || arg.size() != 2 || !arg[0].is_number() || !arg[1].is_number() ||
        !(arg[0].get<double>() >= 0.0) || !(arg[1].get<double>() >= 0.0)) {
      problems.push_back("click_photo needs [X, Y]: a pixel of the loaded photo, not " +
                         detail::cut(arg.dump()));
    }
  } else if (action == "key") {
    if (!arg.is_string() || !parse_chord(arg.get<std::string>())) {
      problems.push_back("key " + detail::cut(arg.dump()) +
                         " is not a chord such as \"ctrl+z\", \"ctrl+shift+z\", \"escape\"");
    }
  } else if (action == "visible" || action == "absent") {
    if (!arg.is_string() || arg.get<std::string>().empty()) {
      problems.push_back(action + " needs the text to look for, not " + detail::cut(arg.dump()));
    }
    if (step.contains("in") && (!step["in"].is_string() || step["in"].get<std::string>().empty())) {
      problems.push_back("\"in\" needs a panel's key (results, parameters, ...), not " +
                         detail::cut(step["in"].dump()));
    }
  } else if (action == "type") {
    if (!arg.is_string()) {
      problems.push_back("type needs a string, not " + detail::cut(arg.dump()));
    }
  } else if (action == "resize") {
    if (!arg.is_string() || !parse_frame_size(arg.get<std::string>())) {
      problems.push_back("resize needs " + frame_size_rule() + ", not " + detail::cut(arg.dump()));
    }
  } else if (action == "frames") {
    if (!arg.is_number_integer() || arg.get<long long>() < 1 || arg.get<long long>() > 100000) {
      problems.push_back("frames needs a whole number from 1 to 100000, not " +
                         detail::cut(arg.dump()));
    }
  } else if (action == "screenshot") {
    if (!arg.is_string() || !arg.get<std::string>().ends_with(".png")) {
      problems.push_back("screenshot needs a file name ending in .png, not " +
                         detail::cut(arg.dump()));
    }
  } else if (action == "expect") {
    if (!arg.is_object() || arg.empty()) {
      problems.push_back("expect needs an object of FIELD.PATH: VALUE or [LO, HI]");
    } else {
      for (const auto& [path, wanted] : arg.items()) {
        const bool range = wanted.is_array() && wanted.size() == 2 && wanted[0].is_number() &&
                           wanted[1].is_number() &&
                           wanted[0].get<double>() <= wanted[1].get<double>();
        if (wanted.is_array() ? !range : wanted.is_object()) {
          problems.push_back("expect " + detail::cut(path) + ": " + detail::cut(wanted.dump()) +
                             " is neither a value nor [LO, HI] with LO <= HI");
        }
      }
    }
  }
  return problems;
}

}  // namespace

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
  long long frames = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::vector<std::string> step = step_problems(steps[i]);
    for (const std::string& problem : step) {
      problems.push_back("step " + std::to_string(i + 1) + ": " + problem);
    }
    if (step.empty() && steps[i].contains("frames")) {
      frames += steps[i].at("frames").get<long long>();
    }
  }
  // Each step is bounded, and so is their sum: 1000 frames of the software renderer take about
  // 20 s, so a script runs for at most about half an hour.
  if (frames > kMaxScriptFrames) {
    problems.push_back("its frames steps add up to " + std::to_string(frames) + ", more than the " +
                       std::to_string(kMaxScriptFrames) + " a script may run");
  }
  return problems;
}

}  // namespace foldlab::gui
