#include "app/cli/export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <regex>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/geometry/geometry.hpp"
#include "core/io/export_budget.hpp"
#include "core/io/io.hpp"
#include "core/io/scene_report.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace export_command {
namespace {

// "--obj", "--glb", ... by kExportFormats' row, kept for the life of the program: a NamedPath
// names its option by a view.
const std::string& flag(std::size_t format) {
  static const std::array<std::string, kExportFormats.size()> flags = [] {
    std::array<std::string, kExportFormats.size()> out;
    for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
      out[i] = "--" + std::string(kExportFormats[i].key);
    }
    return out;
  }();
  return flags[format];
}

struct Outputs {
  std::vector<app::NamedPath> files;
  bool mesh = false;
  bool lines = false;
};

Outputs requested_outputs(const Options& options) {
  Outputs out;
  std::string every_flag;
  for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
    every_flag += (every_flag.empty() ? "" : ", ") + flag(i) + " FILE";
    if (!options.paths[i].empty()) {
      out.files.push_back({flag(i), options.paths[i]});
      (kExportFormats[i].content == ExportFormat::Content::mesh ? out.mesh : out.lines) = true;
    }
  }
  if (out.files.empty()) {
    throw InputError("export needs at least one of " + every_flag);
  }
  return out;
}

struct GridSize {
  int nx = 0;
  int ny = 0;
};

GridSize parse_grid(const std::string& grid) {
  std::smatch match;
  static const std::regex grid_pattern(R"((\d{1,5})x(\d{1,5}))");
  if (!std::regex_match(grid, match, grid_pattern) || std::stoi(match[1]) < 2 ||
      std::stoi(match[2]) < 2 || std::stoi(match[1]) > 4096 || std::stoi(match[2]) > 4096) {
    throw InputError("--grid " + grid +
                     " must be NXxNY, whole numbers from 2 to 4096 with at most " +
                     std::to_string(kMaxExportGridVertices) + " vertices, e.g. 128x128");
  }
  return {std::stoi(match[1]), std::stoi(match[2])};
}

int whole_samples(double samples) {
  if (!(samples >= 2 && samples <= 100000) || samples != std::floor(samples)) {
    throw InputError("--samples " + detail::shortest_number(samples) +
                     " must be a whole number in [2, 100000]");
  }
  return static_cast<int>(samples);
}

// The stderr lines beside the files: the regime's message, and fold lines thinned for drawing.
std::vector<std::string> notes(Scene& scene, bool lines) {
  std::vector<std::string> out;
  const Solution& solution = scene.solution();
  if (std::string message = describe(solution, scene.parameters()); !message.empty()) {
    out.push_back(std::move(message));
  }
  if (lines && scene.fold_lines().stride > 1) {
    // The drawing says so in its corner; the CSV's line numbers show the gaps; say it here too.
    out.push_back(std::to_string(solution.n + 1) + " fold lines are too many to draw: the CSV " +
                  "and SVG hold one line in " + std::to_string(scene.fold_lines().stride) +
                  " (at most " + std::to_string(kMaxDrawnFoldLines) + " lines)");
  }
  return out;
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "export", "write the deformed mesh (OBJ, glTF) and the fold lines (CSV, SVG)");
  add_input_options(*command, options.inputs);
  for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
    command->add_option(flag(i), options.paths[i], std::string(kExportFormats[i].what))
        ->check(app::non_empty_path());
  }
  command->add_option("--grid", options.grid, "mesh resolution NXxNY (default 128x128)");
  command->add_option("--samples", options.samples,
                      "points per fold line, a whole number in [2, 100000] (default 201)");
  command->add_flag("--stats", options.stats,
                    "print the pipeline's per-stage counters as JSON on stdout");
}

Result run(const Options& options) {
  const Outputs outputs = requested_outputs(options);
  const GridSize grid = parse_grid(options.grid);
  const int samples = whole_samples(options.samples);
  check_outputs(outputs.files, {app::preset_input("--preset", options.inputs.preset_path)});
  for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
    std::string format(kExportFormats[i].key);
    std::transform(format.begin(), format.end(), format.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    app::check_output_extension(flag(i), options.paths[i], kExportFormats[i].extension, format);
  }
  if (auto problem = check_grid_budget(grid.nx, grid.ny); problem && outputs.mesh) {
    throw InputError("--grid " + options.grid + ": " + *problem);
  }
  const Preset preset = app::resolve_named_inputs(options.inputs);
  Result result{preset, Scene(preset.parameters), outputs.mesh, outputs.lines, {}};
  Scene& scene = result.scene;
  scene.set_grid_resolution(grid.nx, grid.ny);
  scene.set_fold_line_samples(samples);
  if (result.lines) {
    const std::int64_t points =
        fold_line_point_count(scene.solution(), result.preset.parameters.shape, samples);
    if (auto problem = check_fold_point_budget(points, samples)) {
      throw InputError(*problem);
    }
  }
  result.notes = notes(scene, result.lines);
  if (result.mesh) {
    scene.normals();
  }
  return result;
}

void write_files(const Options& options, Result& result) {
  ExportSource source{.title = result.preset.name};
  if (result.mesh) {
    source.mesh = &result.scene.grid();
  }
  if (result.lines) {
    source.lines = &result.scene.fold_lines();
    source.solution = &result.scene.solution();
  }
  for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
    if (!options.paths[i].empty()) {
      write_file_atomically(options.paths[i], kExportFormats[i].write(source));
    }
  }
}

nlohmann::json print_json(const Result& result) {
  return {{"stats", scene_stats_to_json(result.scene)}};
}

int execute(const Options& options) {
  Result result = run(options);
  write_notes(result.notes, std::cerr);
  write_files(options, result);
  if (options.stats) {
    write_json(print_json(result), std::cout);
  }
  return kExitOk;
}

}  // namespace export_command

Command add_export_command(CLI::App& app) {
  return make_command(app, export_command::declare, export_command::execute);
}

}  // namespace foldlab::cli
