// libFuzzer target for `--set KEY=VALUE`: each line of the input is one assignment. Any text must
// either be applied or give error sentences, never throw or crash. Settings that are applied and
// validate must solve to finite numbers.
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target settings with assignments
// taken from the shipped presets as the seed corpus.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> assignments;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    assignments.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  foldlab::Parameters p;
  const std::vector<std::string> errors = foldlab::apply_assignments(p, assignments);
  for (const std::string& e : errors) {
    if (e.empty()) {
      std::abort();  // an error without a sentence
    }
  }
  if (!errors.empty() || !foldlab::validate(p).empty()) {
    return 0;
  }
  const foldlab::Solution s = foldlab::solve(p);
  if (!std::isfinite(s.Q) || !std::isfinite(s.z_max_mm) || s.n < 0) {
    std::abort();  // valid inputs gave a non-finite result
  }
  return 0;
}
