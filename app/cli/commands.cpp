#include "app/cli/commands.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <regex>

#include <nlohmann/json.hpp>

#include "app/common/inputs.hpp"
#include "app/common/presets_dir.hpp"
#include "core/analysis/comparison.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/geometry/geometry.hpp"
#include "core/geometry/scene.hpp"
#include "core/io/export.hpp"
#include "core/io/export_budget.hpp"
#include "core/io/export_formats.hpp"
#include "core/io/io.hpp"
#include "core/io/report.hpp"
#include "core/io/scene_report.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {

Command add_solve_command(CLI::App& app) {
  struct Options {
    InputOptions inputs;
    bool json = false;
    bool stats = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("solve", "solve one case and print the result");
  add_input_options(*command, options->inputs);
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  command->add_flag("--stats", options->stats,
                    "add the pipeline's per-stage counters (evaluations, time)");
  return [options] {
    return guarded([&] {
      const Preset preset = resolve_inputs(options->inputs);
      Scene scene(preset.parameters);
      const Solution& solution = scene.solution();
      const ModelStanding standing = model_standing(preset.parameters, preset.calibration);
      if (options->json) {
        nlohmann::json out = solution_to_json(solution, preset.parameters, &standing);
        if (options->stats) {
          out["stats"] = scene_stats_to_json(scene);
        }
        std::cout << out.dump(2) << "\n";
      } else {
        std::cout << solution_table(solution, preset.parameters, preset.name, &standing);
        if (options->stats) {
          std::cout << "\n" << scene_stats_table(scene);
        }
      }
      return kExitOk;
    });
  };
}

Command add_export_command(CLI::App& app) {
  struct Options {
    InputOptions inputs;
    std::array<std::string, kExportFormats.size()> flags;  // by kExportFormats' row: "--obj"
    std::array<std::string, kExportFormats.size()> paths;
    std::string grid = "128x128";
    double samples = 201;
    bool stats = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "export", "write the deformed mesh (OBJ, glTF) and the fold lines (CSV, SVG)");
  add_input_options(*command, options->inputs);
  for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
    options->flags[i] = "--" + std::string(kExportFormats[i].key);
    command->add_option(options->flags[i], options->paths[i], std::string(kExportFormats[i].what))
        ->check(app::non_empty_path());
  }
  command->add_option("--grid", options->grid, "mesh resolution NXxNY (default 128x128)");
  command->add_option("--samples", options->samples,
                      "points per fold line, a whole number in [2, 100000] (default 201)");
  command->add_flag("--stats", options->stats,
                    "print the pipeline's per-stage counters as JSON on stdout");
  return [options] {
    return guarded([&] {
      std::vector<app::NamedPath> outputs;
      std::string every_flag;
      bool mesh = false;
      bool lines = false;
      for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
        const std::string& flag = options->flags[i];
        every_flag += (every_flag.empty() ? "" : ", ") + flag + " FILE";
        if (!options->paths[i].empty()) {
          outputs.push_back({flag, options->paths[i]});
          (kExportFormats[i].content == ExportFormat::Content::mesh ? mesh : lines) = true;
        }
      }
      if (outputs.empty()) {
        throw InputError("export needs at least one of " + every_flag);
      }
      std::smatch match;
      static const std::regex grid_pattern(R"((\d{1,5})x(\d{1,5}))");
      if (!std::regex_match(options->grid, match, grid_pattern) || std::stoi(match[1]) < 2 ||
          std::stoi(match[2]) < 2 || std::stoi(match[1]) > 4096 || std::stoi(match[2]) > 4096) {
        throw InputError("--grid " + options->grid +
                         " must be NXxNY, whole numbers from 2 to 4096 with at most " +
                         std::to_string(kMaxExportGridVertices) + " vertices, e.g. 128x128");
      }
      // Parsed as a number, not an integer, so that 1e3 means 1000 rather than a puzzling refusal.
      if (!(options->samples >= 2 && options->samples <= 100000) ||
          options->samples != std::floor(options->samples)) {
        throw InputError("--samples " + detail::shortest_number(options->samples) +
                         " must be a whole number in [2, 100000]");
      }
      const int samples = static_cast<int>(options->samples);
      check_distinct_files(outputs, {{"--preset", options->inputs.preset_path}});
      const int nx = std::stoi(match[1]);
      const int ny = std::stoi(match[2]);
      if (auto problem = check_grid_budget(nx, ny); problem && mesh) {
        throw InputError("--grid " + options->grid + ": " + *problem);
      }
      const Preset preset = resolve_inputs(options->inputs);
      // Only the stages an output asks for run: an SVG alone builds no grid.
      Scene scene(preset.parameters);
      scene.set_grid_resolution(nx, ny);
      scene.set_fold_line_samples(samples);
      const Solution& solution = scene.solution();
      if (lines) {
        const std::int64_t points =
            fold_line_point_count(solution, preset.parameters.shape, samples);
        if (auto problem = check_fold_point_budget(points, samples)) {
          throw InputError(*problem);
        }
      }
      if (const std::string message = describe(solution, preset.parameters); !message.empty()) {
        std::cerr << "foldlab: " << message << "\n";
      }
      if (lines && scene.fold_lines().stride > 1) {
        // The drawing says so in its corner; the CSV's line numbers show the gaps; say it here too.
        std::cerr << "foldlab: " << solution.n + 1 << " fold lines are too many to draw: the CSV "
                  << "and SVG hold one line in " << scene.fold_lines().stride << " (at most "
                  << kMaxDrawnFoldLines << " lines)\n";
      }
      ExportSource source{.title = preset.name};
      if (mesh) {
        scene.normals();
        source.mesh = &scene.grid();
      }
      if (lines) {
        source.lines = &scene.fold_lines();
        source.solution = &solution;
      }
      for (std::size_t i = 0; i < kExportFormats.size(); ++i) {
        if (!options->paths[i].empty()) {
          write_file_atomically(options->paths[i], kExportFormats[i].write(source));
        }
      }
      if (options->stats) {
        std::cout << nlohmann::json{{"stats", scene_stats_to_json(scene)}}.dump(2) << "\n";
      }
      return kExitOk;
    });
  };
}

namespace {

// How close the model gets to the published results, one group of rows at a time: the paper's
// tables (and Fig. 4) are told apart by the part of a preset's name before its first comma
// ("Table 1, h = 900 mm" is in "Table 1"); a name without a comma is a group of its own.
struct PublishedGroupAccuracy {
  std::string group;
  int rows = 0;
  ComparisonSummary method[2];  // [paper, exact]
};

std::string published_group(const std::string& preset_name) {
  return preset_name.substr(0, preset_name.find(','));
}

std::vector<PublishedGroupAccuracy> accuracy_by_group(
    const std::vector<Preset>& presets, const std::vector<std::vector<PublishedComparison>>& rows) {
  std::vector<std::string> groups;  // in the order the presets first name them
  for (const Preset& preset : presets) {
    const std::string group = published_group(preset.name);
    if (std::find(groups.begin(), groups.end(), group) == groups.end()) {
      groups.push_back(group);
    }
  }
  std::vector<PublishedGroupAccuracy> out;
  for (const std::string& group : groups) {
    PublishedGroupAccuracy accuracy;
    accuracy.group = group;
    std::vector<PublishedComparison> in_group[2];
    for (std::size_t i = 0; i < presets.size(); ++i) {
      if (published_group(presets[i].name) == group) {
        ++accuracy.rows;
        for (std::size_t m = 0; m < 2; ++m) {
          in_group[m].push_back(rows[m][i]);
        }
      }
    }
    for (std::size_t m = 0; m < 2; ++m) {
      accuracy.method[m] = summarize(in_group[m]);
    }
    out.push_back(std::move(accuracy));
  }
  return out;
}

nlohmann::json accuracy_to_json(const ComparisonSummary& s) {
  const auto error = [](int count, double median) {
    return count == 0 ? nlohmann::json() : nlohmann::json(median);
  };
  return {{"rows_with_n", s.rows_with_n},
          {"n_exact", s.n_exact},
          {"n_within_one", s.n_within_one},
          {"rows_with_z", s.rows_with_z},
          {"median_abs_z_error", error(s.rows_with_z, s.median_abs_z_error)},
          {"rows_with_Q", s.rows_with_Q},
          {"median_abs_Q_error", error(s.rows_with_Q, s.median_abs_Q_error)}};
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> presets;
    std::vector<std::string> assignments;
    std::string law;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "compare", "both methods beside the published n, z_max and Q of presets that carry them");
  command->add_option("--preset", options->presets,
                      "preset files (default: every preset in the presets folder with published "
                      "results)");
  command->add_option("--set", options->assignments, "override an input of every preset, KEY=VALUE")
      ->type_name("KEY=VALUE");
  app::add_law_option(*command, options->law);
  command->add_flag("--json", options->json, "print JSON instead of a Markdown table");
  return [options] {
    return guarded([&] {
      std::vector<std::string> paths = options->presets;
      if (paths.empty()) {
        const std::filesystem::path dir = find_presets_dir();
        if (dir.empty()) {
          throw InputError("no presets folder found: name presets with --preset");
        }
        for (const auto& file : preset_files(dir)) {
          paths.push_back(file.string());
        }
      }
      std::vector<Preset> presets;
      std::vector<std::vector<PublishedComparison>> rows(2);  // [paper, exact]
      for (const std::string& path : paths) {
        InputOptions inputs{path, options->assignments, "", options->law};
        Preset preset = resolve_inputs(inputs);
        const PublishedResult& pub = preset.published;
        if (!pub.n && !pub.z_max_mm && !pub.Q) {
          continue;
        }
        for (Method m : {Method::paper, Method::exact}) {
          Parameters p = preset.parameters;
          p.model.method = m;
          rows[m == Method::paper ? 0 : 1].push_back(compare_with_published(pub, p));
        }
        presets.push_back(std::move(preset));
      }
      if (presets.empty()) {
        throw InputError("none of the presets carries published results");
      }
      const std::vector<PublishedGroupAccuracy> accuracy = accuracy_by_group(presets, rows);
      if (options->json) {
        nlohmann::json out = {{"rows", nlohmann::json::array()},
                              {"accuracy_by_table", nlohmann::json::array()}};
        for (std::size_t i = 0; i < presets.size(); ++i) {
          nlohmann::json row = {{"name", presets[i].name}};
          for (int m = 0; m < 2; ++m) {
            const PublishedComparison& c = rows[static_cast<std::size_t>(m)][i];
            row[m == 0 ? "paper" : "exact"] = {{"n", c.solution.n},
                                               {"n_capped", c.solution.n_capped},
                                               {"z_max_mm", c.solution.z_max_mm},
                                               {"Q", c.solution.Q}};
          }
          const PublishedResult& pub = presets[i].published;
          row["published"] = {
              {"n", pub.n ? nlohmann::json(*pub.n) : nlohmann::json()},
              {"z_max_mm", pub.z_max_mm ? nlohmann::json(*pub.z_max_mm) : nlohmann::json()},
              {"Q", pub.Q ? nlohmann::json(*pub.Q) : nlohmann::json()}};
          out["rows"].push_back(row);
        }
        for (const PublishedGroupAccuracy& group : accuracy) {
          out["accuracy_by_table"].push_back({{"table", group.group},
                                              {"rows", group.rows},
                                              {"paper", accuracy_to_json(group.method[0])},
                                              {"exact", accuracy_to_json(group.method[1])}});
        }
        std::cout << out.dump(2) << "\n";
        return kExitOk;
      }
      auto optional_number = [](const auto& value, const char* format) -> std::string {
        if (!value) {
          return "–";
        }
        char text[32];
        std::snprintf(text, sizeof text, format, static_cast<double>(*value));
        return text;
      };
      auto with_error = [](double value, const std::optional<double>& error, const char* format) {
        char text[64];
        std::snprintf(text, sizeof text, format, value);
        std::string out = text;
        if (error) {
          std::snprintf(text, sizeof text, " (%+.1f%%)", 100.0 * *error);
          out += text;
        }
        return out;
      };
      std::cout
          << "| case | paper n | paper z_max (mm) | paper Q | paper method n | z_max (mm) | Q "
             "| exact method n | z_max (mm) | Q |\n"
             "|---|---|---|---|---|---|---|---|---|---|\n";
      for (std::size_t i = 0; i < presets.size(); ++i) {
        const PublishedResult& pub = presets[i].published;
        std::cout << "| " << detail::markdown_cell(presets[i].name) << " | "
                  << optional_number(pub.n, "%.0f") << " | " << optional_number(pub.z_max_mm, "%g")
                  << " | " << optional_number(pub.Q, "%.2f");
        for (int m = 0; m < 2; ++m) {
          const PublishedComparison& c = rows[static_cast<std::size_t>(m)][i];
          // "+" as in `sweep`: eq. 10 asked for more folds than the cap, which is shown.
          std::cout << " | " << c.solution.n << (c.solution.n_capped ? "+ (capped)" : "") << " | "
                    << with_error(c.solution.z_max_mm, c.z_error, "%.1f") << " | "
                    << with_error(c.solution.Q, c.Q_error, "%.3f");
        }
        std::cout << " |\n";
      }
      std::cout << "\n";
      for (int m = 0; m < 2; ++m) {
        const ComparisonSummary sum = summarize(rows[static_cast<std::size_t>(m)]);
        std::cout << (m == 0 ? "paper" : "exact") << " method: " << summary_text(sum) << "\n";
      }
      // How close the model gets to each of the paper's tables, as counted above: what the
      // model is worth against the paper, not a tolerance that any test was fitted to.
      std::cout << "\nPaper accuracy by table:\n\n"
                   "| table | rows | paper method n exact | n within ±1 | median \\|z_max error\\| "
                   "| exact method n exact | n within ±1 | median \\|z_max error\\| |\n"
                   "|---|---|---|---|---|---|---|---|\n";
      for (const PublishedGroupAccuracy& group : accuracy) {
        std::cout << "| " << detail::markdown_cell(group.group) << " | " << group.rows;
        for (const ComparisonSummary& s : group.method) {
          std::cout << " | " << s.n_exact << "/" << s.rows_with_n << " | " << s.n_within_one << "/"
                    << s.rows_with_n << " | "
                    << (s.rows_with_z == 0
                            ? std::string("–")
                            : detail::printf_string("%.1f %%", 100.0 * s.median_abs_z_error));
        }
        std::cout << " |\n";
      }
      return kExitOk;
    });
  };
}

int run_default_headless() {
  return guarded([] {
    const Preset& preset = default_preset();
    const Solution solution = solve(preset.parameters);
    const ModelStanding standing = model_standing(preset.parameters, preset.calibration);
    std::cout << solution_table(solution, preset.parameters, preset.name, &standing);
    return kExitOk;
  });
}

}  // namespace foldlab::cli
