#include "cli/inputs.hpp"

#include "foldlab/settings.hpp"

namespace foldlab::cli {

Preset resolve_inputs(const InputOptions& options) {
  Preset preset;
  try {
    preset = options.preset_path.empty() ? default_preset() : load_preset(options.preset_path);
  } catch (const PresetError& e) {
    throw InputError(e.what());
  }
  std::vector<std::string> assignments = options.assignments;
  if (!options.method.empty()) {
    assignments.push_back("method=" + options.method);
  }
  std::string problems;
  for (const std::string& error : apply_assignments(preset.parameters, assignments)) {
    problems += "--set " + error + "\n";
  }
  if (problems.empty()) {
    problems = format_issues(validate(preset.parameters));
  }
  if (!problems.empty()) {
    problems.pop_back();  // the final newline
    throw InputError(problems);
  }
  return preset;
}

}  // namespace foldlab::cli
