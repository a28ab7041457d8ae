// libFuzzer target for the explorer's session.json reader: any text must either give a session or
// a sentence saying why not (the explorer then starts from its defaults). What it gives must be
// usable as is: both presets valid, the grid resolution within the slider's range.
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target session with the shipped
// presets wrapped into sessions as the seed corpus.
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "app/gui/session.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const std::optional<foldlab::gui::Session> session =
      foldlab::gui::session_from_text(text, "<fuzz>", error);
  if (!session) {
    if (error.empty()) {
      std::abort();  // refused without saying why
    }
    return 0;
  }
  if ((session->fabric_restored && (!foldlab::validate(session->current.parameters).empty() ||
                                    !foldlab::validate(session->loaded.parameters).empty())) ||
      session->grid_resolution < foldlab::gui::kMinGridResolution ||
      session->grid_resolution > foldlab::gui::kMaxGridResolution) {
    std::abort();  // accepted a session the explorer cannot use as is
  }
  return 0;
}
