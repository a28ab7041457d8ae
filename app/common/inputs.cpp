#include "app/common/inputs.hpp"

#include <iostream>

#include "core/io/io.hpp"
#include "core/model/settings.hpp"

namespace foldlab::app {

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
  // Range problems as well: a value that did not parse left the preset's (valid) value in place,
  // so every range problem reported is a real one.
  problems += format_issues(validate(preset.parameters));
  if (!problems.empty()) {
    problems.pop_back();  // the final newline
    throw InputError(problems);
  }
  return preset;
}

void add_input_options(CLI::App& command, InputOptions& options) {
  command.add_option(
      "--preset", options.preset_path,
      "preset JSON file (default: the built-in presets/default.json, eq. 7 calibrated on "
      "Conci's Tables 1–2)");
  std::string keys;
  for (const InputSpec& spec : input_table()) {
    keys += "\n    " + input_label(spec) + ": " + std::string(spec.help);
  }
  command.add_option("--set", options.assignments, "override an input, KEY=VALUE; keys:" + keys)
      ->type_name("KEY=VALUE");
  command.add_option("--method", options.method, "solution method (default: the preset's)")
      ->check(CLI::IsMember({"paper", "exact"}));
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::cerr << "foldlab: invalid input:\n" << e.what() << "\n";
    return kExitInvalidInput;
  } catch (const PresetError& e) {
    std::cerr << "foldlab: invalid input:\n" << e.what() << "\n";
    return kExitInvalidInput;
  } catch (const EnvironmentError& e) {
    std::cerr << "foldlab: " << e.what() << "\n";
    return kExitInternal;
  } catch (const WriteError& e) {
    std::cerr << "foldlab: " << e.what() << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "foldlab: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace foldlab::app
