// libFuzzer target for the preset loader: any text must either load or be rejected with a
// PresetError (whose message names the problems). Anything else escaping, a crash, or a sanitizer
// report is a failure. What loads must also be solvable (validate() empty) and survive a round
// trip through JSON unchanged.
//
// Built with clang++ -fsanitize=fuzzer,address,undefined (tests/fuzz/CMakeLists.txt); run for a
// bounded time by scripts/fuzz.sh with presets/*.json as the seed corpus.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "core/io/preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  foldlab::Preset preset;
  try {
    preset = foldlab::preset_from_text(text, "<fuzz>");
  } catch (const foldlab::PresetError&) {
    return 0;  // rejected with a message, as promised
  }
  if (!foldlab::validate(preset.parameters).empty()) {
    std::abort();  // accepted input that cannot be solved
  }
  const foldlab::Preset back =
      foldlab::preset_from_json(foldlab::preset_to_json(preset), "<round trip>");
  if (!(back.parameters == preset.parameters) || back.name != preset.name ||
      back.published.n != preset.published.n || back.published.Q != preset.published.Q ||
      back.published.z_max_mm != preset.published.z_max_mm) {
    std::abort();  // saving and loading again would change the preset
  }
  return 0;
}
