// libFuzzer target for `--set KEY=VALUE`: each line of the input is one assignment. Any text must
// either be applied or give error sentences, never throw or crash. Whatever was applied, refused
// or not, must come back bit for bit through its link (core/io/link.hpp), and the whole input read
// as a link must give sentences too. Settings that are applied and validate must solve to finite
// numbers.
//
// Built by tests/fuzz/CMakeLists.txt; run by scripts/fuzz.sh --target settings with assignments
// taken from the shipped presets as the seed corpus.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/io/link.hpp"
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
  // A K typed at an absurd nu can make c infinite or NaN, which no text reads back as.
  const bool finite = std::all_of(foldlab::input_table().begin(), foldlab::input_table().end(),
                                  [&](const foldlab::InputSpec& spec) {
                                    const std::optional<double> value = spec.value(p);
                                    return !value || std::isfinite(*value);
                                  });
  if (finite) {
    std::vector<std::string> linked;
    for (const foldlab::LinkAssignment& piece :
         foldlab::parse_fabric_link(foldlab::fabric_link(p))) {
      linked.push_back(piece.set_text());
    }
    foldlab::Parameters back;
    if (!foldlab::apply_assignments(back, linked).empty() || !(back == p)) {
      std::abort();  // the link of what was applied does not bring it back
    }
    for (const foldlab::InputSpec& spec : foldlab::input_table()) {
      const std::optional<double> a = spec.value(p);
      const std::optional<double> b = spec.value(back);
      if (a && std::memcmp(&*a, &*b, sizeof(double)) != 0) {
        std::abort();  // equal, but not the same bits (-0 for 0)
      }
    }
  }
  std::vector<std::string> pieces;
  for (const foldlab::LinkAssignment& piece : foldlab::parse_fabric_link(text)) {
    pieces.push_back(piece.set_text());
  }
  foldlab::Parameters from_link;
  for (const std::string& e : foldlab::apply_assignments(from_link, pieces)) {
    if (e.empty()) {
      std::abort();
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
