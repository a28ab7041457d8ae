// libFuzzer target for `--play` scripts, checked as the explorer checks them before any frame
// runs (play_script_problems, no window): any text must either be refused with problems, each one
// printable line, or pass, and then every step the player later trusts without checking again (a
// key's chord, a resize's size) must read.
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target play_script with
// tests/play/*.json as the seed corpus.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "app/gui/play_script.hpp"
#include "app/gui/surface.hpp"
#include "core/io/json_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json script;
  try {
    script = foldlab::parse_json(text, "<fuzz>");
  } catch (const foldlab::JsonInputError&) {
    return 0;
  }
  const std::vector<std::string> problems = foldlab::gui::play_script_problems(script);
  for (const std::string& problem : problems) {
    for (const char c : problem) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte < 0x20 || byte == 0x7F) {
        std::abort();  // a control character from the script echoed raw
      }
    }
    if (problem.size() > 2000) {
      std::abort();  // a problem line that quotes the whole script
    }
  }
  if (!problems.empty()) {
    return 0;
  }
  for (const nlohmann::json& step : script.at("steps")) {
    if (step.contains("key") && !foldlab::gui::parse_chord(step.at("key").get<std::string>())) {
      std::abort();
    }
    if (step.contains("resize") &&
        !foldlab::gui::parse_frame_size(step.at("resize").get<std::string>())) {
      std::abort();
    }
  }
  return 0;
}
