// libFuzzer target for a preset's stored calibration block: the input is the value of
// "calibration" in the built-in default preset. It must either load or be refused with a
// PresetError; what loads must hold at most kMaxCalibrationEntries constants per list, each in
// the input table's ranges (K as c at the preset's nu, p in p's row), and survive a round trip.
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target calibration with the
// shipped presets' calibration blocks as the seed corpus.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/json_input.hpp"
#include "core/io/preset.hpp"
#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"

namespace {

bool in_range(const foldlab::Eq7Constants& k, double nu) {
  return foldlab::find_input("c")->valid.contains(k.K * (1.0 - nu * nu)) &&
         foldlab::find_input("p")->valid.contains(k.p);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json block;
  try {
    block = foldlab::parse_json(text, "<fuzz>");
  } catch (const foldlab::JsonInputError&) {
    return 0;
  }
  static const nlohmann::json base = foldlab::preset_to_json(foldlab::default_preset());
  nlohmann::json j = base;
  j["calibration"] = block;
  foldlab::Preset preset;
  try {
    preset = foldlab::preset_from_json(j, "<fuzz>");
  } catch (const foldlab::PresetError&) {
    return 0;
  }
  if (!preset.calibration) {
    std::abort();  // a block given but none kept
  }
  const foldlab::CalibrationRecord& record = *preset.calibration;
  const double nu = preset.parameters.fabric.poisson_ratio;
  if (record.equally_good.size() > foldlab::kMaxCalibrationEntries ||
      record.leave_one_out.size() > foldlab::kMaxCalibrationEntries || record.fit_rows < 0 ||
      !in_range(record.fitted, nu)) {
    std::abort();
  }
  for (const auto* list : {&record.equally_good, &record.leave_one_out}) {
    for (const foldlab::Eq7Constants& k : *list) {
      if (!in_range(k, nu)) {
        std::abort();  // a stored constant outside the input table's ranges
      }
    }
  }
  const foldlab::Preset back =
      foldlab::preset_from_json(foldlab::preset_to_json(preset), "<round trip>");
  if (!(back.calibration == preset.calibration)) {
    std::abort();
  }
  return 0;
}
