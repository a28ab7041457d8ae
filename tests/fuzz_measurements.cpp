// libFuzzer target for the measurements loader: any text, read as CSV and as JSON, must either load
// or be rejected with a MeasurementError. Anything else escaping, a crash, or a sanitizer report is
// a failure. What loads must survive a round trip: writing its rows as CSV and reading that back
// gives the same CSV. (The description and source become CSV comments, which a reader skips.)
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target measurements with data/* as
// the seed corpus.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/io/measurements.hpp"

namespace {

void check_round_trip(foldlab::MeasurementSet set) {
  set.description.clear();
  set.source.clear();
  const std::string csv = foldlab::measurements_to_csv(set);
  foldlab::MeasurementSet back;
  try {
    back = foldlab::measurements_from_csv(csv, "<round trip>");
  } catch (const foldlab::MeasurementError&) {
    std::abort();  // what was accepted is written in a form that is refused
  }
  if (foldlab::measurements_to_csv(back) != csv || back.rows.size() != set.rows.size()) {
    std::abort();  // saving and loading again would change the measurements
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* extension : {".csv", ".json"}) {
    try {
      check_round_trip(foldlab::measurements_from_text(text, "<fuzz>", extension));
    } catch (const foldlab::MeasurementError&) {
      // rejected with a message, as promised
    }
  }
  return 0;
}
