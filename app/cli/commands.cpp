#include "cli/commands.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <regex>

#include <nlohmann/json.hpp>

#include "cli/inputs.hpp"
#include "foldlab/export.hpp"
#include "foldlab/geometry.hpp"
#include "foldlab/io.hpp"
#include "foldlab/report.hpp"
#include "foldlab/settings.hpp"
#include "foldlab/solver.hpp"

namespace foldlab::cli {
namespace {

// --preset, --set and --method, shared by every command that solves.
void add_input_options(CLI::App& command, InputOptions& options) {
  command.add_option("--preset", options.preset_path,
                     "preset JSON file (default: the built-in Table 1, h = 1400 mm preset)");
  std::string keys;
  for (const SettingKey& k : setting_keys()) {
    keys += "\n    " + std::string(k.key) + (k.unit.empty() ? "" : " (" + std::string(k.unit) + ")") +
            ": " + std::string(k.description);
  }
  command.add_option("--set", options.assignments, "override an input, KEY=VALUE; keys:" + keys)
      ->type_name("KEY=VALUE");
  command.add_option("--method", options.method, "solution method (default: the preset's)")
      ->check(CLI::IsMember({"paper", "exact"}));
}

// Runs `body`, turning InputError into exit 2 and anything else into exit 1, messages on stderr.
int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::cerr << "foldlab: invalid input:\n" << e.what() << "\n";
    return kExitInvalidInput;
  } catch (const WriteError& e) {
    std::cerr << "foldlab: " << e.what() << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "foldlab: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace

Command add_solve_command(CLI::App& app) {
  struct Options {
    InputOptions inputs;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("solve", "solve one case and print the result");
  add_input_options(*command, options->inputs);
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  return [options] {
    return guarded([&] {
      const Preset preset = resolve_inputs(options->inputs);
      const Solution solution = solve(preset.parameters);
      if (options->json) {
        std::cout << solution_to_json(solution, preset.parameters).dump(2) << "\n";
      } else {
        std::cout << solution_table(solution, preset.parameters, preset.name);
      }
      return kExitOk;
    });
  };
}

Command add_export_command(CLI::App& app) {
  struct Options {
    InputOptions inputs;
    std::string obj_path;
    std::string csv_path;
    std::string svg_path;
    std::string grid = "128x128";
    int samples = 201;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "export", "write the deformed mesh (OBJ) and the fold lines (CSV, SVG)");
  add_input_options(*command, options->inputs);
  CLI::Option* obj = command->add_option("--obj", options->obj_path, "deformed mesh, Wavefront OBJ");
  CLI::Option* csv = command->add_option("--csv", options->csv_path, "fold lines as CSV");
  CLI::Option* svg = command->add_option("--svg", options->svg_path, "fold lines as an SVG drawing");
  command->add_option("--grid", options->grid, "mesh resolution NXxNY (default 128x128)");
  command->add_option("--samples", options->samples, "points per fold line (default 201)")
      ->check(CLI::Range(2, 100000));
  (void)obj;
  (void)csv;
  (void)svg;
  return [options] {
    return guarded([&] {
      if (options->obj_path.empty() && options->csv_path.empty() && options->svg_path.empty()) {
        throw InputError("export needs at least one of --obj FILE, --csv FILE, --svg FILE");
      }
      std::smatch match;
      static const std::regex grid_pattern(R"((\d{1,5})x(\d{1,5}))");
      if (!std::regex_match(options->grid, match, grid_pattern) || std::stoi(match[1]) < 2 ||
          std::stoi(match[2]) < 2 || std::stoi(match[1]) > 4096 || std::stoi(match[2]) > 4096) {
        throw InputError("--grid " + options->grid +
                         " must be NXxNY with 2 <= NX, NY <= 4096, e.g. 128x128");
      }
      const int nx = std::stoi(match[1]);
      const int ny = std::stoi(match[2]);
      const Preset preset = resolve_inputs(options->inputs);
      const Solution solution = solve(preset.parameters);
      if (const std::string message = describe(solution, preset.parameters); !message.empty()) {
        std::cerr << "foldlab: " << message << "\n";
      }
      if (!options->obj_path.empty()) {
        const DeformedGrid grid = deformed_grid(solution, preset.parameters, nx, ny);
        write_file_atomically(options->obj_path, mesh_to_obj(grid, preset.name));
      }
      if (!options->csv_path.empty() || !options->svg_path.empty()) {
        const FoldLines lines = fold_lines(solution, options->samples);
        if (!options->csv_path.empty()) {
          write_file_atomically(options->csv_path, fold_lines_to_csv(lines));
        }
        if (!options->svg_path.empty()) {
          write_file_atomically(options->svg_path, fold_lines_to_svg(lines, solution, preset.name));
        }
      }
      return kExitOk;
    });
  };
}

int run_default_headless() {
  return guarded([] {
    const Preset& preset = default_preset();
    const Solution solution = solve(preset.parameters);
    std::cout << solution_table(solution, preset.parameters, preset.name);
    return kExitOk;
  });
}

}  // namespace foldlab::cli
